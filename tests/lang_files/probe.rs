//! Model probes: a path into the scene's `Debug` form, compared with a value written the
//! same way (`<1, 2, 3>` for any three numbers, `Name { field: value }` matching the fields
//! it names), or a transform found on that path applied to a point.

/// A parsed `Debug` rendering (or an expected value written like one).
#[derive(Clone, Debug)]
pub enum Node {
    /// A number, identifier, string or `true`/`false`.
    Atom(String),
    /// `Name { .. }` or `Name(..)`.
    Named(String, Box<Node>),
    Struct(Vec<(String, Node)>),
    /// `( .. )`, or `< .. >` in expected values.
    Tuple(Vec<Node>),
    List(Vec<Node>),
}

impl std::fmt::Display for Node {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let join = |items: &[Node]| {
            let parts: Vec<String> = items.iter().map(Node::to_string).collect();
            parts.join(", ")
        };
        match self {
            Node::Atom(a) => write!(f, "{a}"),
            Node::Named(n, inner) => match &**inner {
                Node::Struct(_) => write!(f, "{n} {inner}"),
                _ => write!(f, "{n}{inner}"),
            },
            Node::Struct(fields) => {
                let parts: Vec<String> = fields.iter().map(|(k, v)| format!("{k}: {v}")).collect();
                write!(f, "{{ {} }}", parts.join(", "))
            }
            Node::Tuple(items) => write!(f, "({})", join(items)),
            Node::List(items) => write!(f, "[{}]", join(items)),
        }
    }
}

fn tokens(text: &str) -> Vec<String> {
    let chars: Vec<char> = text.chars().collect();
    let mut out = Vec::new();
    let mut i = 0;
    while i < chars.len() {
        let c = chars[i];
        if c.is_whitespace() {
            i += 1;
        } else if c == '"' {
            let start = i;
            i += 1;
            while i < chars.len() && chars[i] != '"' {
                i += if chars[i] == '\\' { 2 } else { 1 };
            }
            i = (i + 1).min(chars.len());
            out.push(chars[start..i].iter().collect());
        } else if "{}()[]<>,:".contains(c) {
            out.push(c.to_string());
            i += 1;
        } else {
            let start = i;
            while i < chars.len() && !chars[i].is_whitespace() && !"{}()[]<>,:\"".contains(chars[i])
            {
                i += 1;
            }
            out.push(chars[start..i].iter().collect());
        }
    }
    out
}

struct Parser {
    toks: Vec<String>,
    at: usize,
}

impl Parser {
    fn peek(&self) -> Option<&str> {
        self.toks.get(self.at).map(String::as_str)
    }

    fn next(&mut self) -> Result<String, String> {
        let t = self.toks.get(self.at).cloned().ok_or("unexpected end")?;
        self.at += 1;
        Ok(t)
    }

    fn items(&mut self, close: &str) -> Result<Vec<Node>, String> {
        let mut items = Vec::new();
        while self.peek() != Some(close) {
            items.push(self.value()?);
            if self.peek() == Some(",") {
                self.at += 1;
            }
        }
        self.at += 1;
        Ok(items)
    }

    fn fields(&mut self) -> Result<Vec<(String, Node)>, String> {
        let mut fields = Vec::new();
        while self.peek() != Some("}") {
            let key = self.next()?;
            if self.next()? != ":" {
                return Err(format!("expected `:` after `{key}`"));
            }
            fields.push((key, self.value()?));
            if self.peek() == Some(",") {
                self.at += 1;
            }
        }
        self.at += 1;
        Ok(fields)
    }

    fn value(&mut self) -> Result<Node, String> {
        let t = self.next()?;
        match t.as_str() {
            "[" => Ok(Node::List(self.items("]")?)),
            "(" => Ok(Node::Tuple(self.items(")")?)),
            "<" => Ok(Node::Tuple(self.items(">")?)),
            "{" => Ok(Node::Struct(self.fields()?)),
            "}" | ")" | "]" | ">" | "," | ":" => Err(format!("unexpected `{t}`")),
            _ => match self.peek() {
                Some("{") => {
                    self.at += 1;
                    Ok(Node::Named(t, Box::new(Node::Struct(self.fields()?))))
                }
                Some("(") => {
                    self.at += 1;
                    Ok(Node::Named(t, Box::new(Node::Tuple(self.items(")")?))))
                }
                // `rgbft <1, 1, 1, 0, 0>`, as global colours print.
                Some("<") => {
                    self.at += 1;
                    Ok(Node::Named(t, Box::new(Node::Tuple(self.items(">")?))))
                }
                _ => Ok(Node::Atom(t)),
            },
        }
    }
}

/// Parses a `Debug` rendering or an expected value.
pub fn parse(text: &str) -> Result<Node, String> {
    let mut p = Parser {
        toks: tokens(text),
        at: 0,
    };
    let v = p.value()?;
    match p.peek() {
        None => Ok(v),
        Some(t) => Err(format!("unexpected `{t}` after the value")),
    }
}

fn segments(path: &str) -> Vec<String> {
    path.replace('[', ".[")
        .split('.')
        .filter(|s| !s.is_empty())
        .map(str::to_string)
        .collect()
}

/// Follows `objects[0].shape.Sphere.radius`: fields, `[i]` indices, `.0` tuple items,
/// a variant name (which must match), `len` of a list; `Some` is looked through.
pub fn follow<'n>(root: &'n Node, path: &str) -> Result<std::borrow::Cow<'n, Node>, String> {
    let mut node = std::borrow::Cow::Borrowed(root);
    for seg in segments(path) {
        let next = step(&node, &seg).ok_or_else(|| format!("no `{seg}` in {}", short(&node)))?;
        node = std::borrow::Cow::Owned(next);
    }
    Ok(node)
}

fn short(node: &Node) -> String {
    let s = node.to_string();
    if s.chars().count() > 300 {
        format!("{}...", s.chars().take(300).collect::<String>())
    } else {
        s
    }
}

fn step(node: &Node, seg: &str) -> Option<Node> {
    let index = seg
        .strip_prefix('[')
        .and_then(|s| s.strip_suffix(']'))
        .or(Some(seg).filter(|s| s.chars().all(|c| c.is_ascii_digit())))
        .and_then(|s| s.parse::<usize>().ok());
    match node {
        Node::Named(name, inner) if name == seg => Some((**inner).clone()),
        Node::Named(name, inner) => match (&**inner, name.as_str()) {
            (Node::Tuple(items), "Some") if items.len() == 1 && index.is_none() => {
                step(&items[0], seg)
            }
            _ => step(inner, seg),
        },
        Node::Struct(fields) => fields
            .iter()
            .find(|(k, _)| k == seg)
            .map(|(_, v)| v.clone()),
        Node::Tuple(items) | Node::List(items) if seg == "len" => {
            Some(Node::Atom(items.len().to_string()))
        }
        Node::Tuple(items) | Node::List(items) => index.and_then(|i| items.get(i)).cloned(),
        Node::Atom(_) => None,
    }
}

fn number(s: &str) -> Option<f64> {
    match s {
        "true" => Some(1.0),
        "false" => Some(0.0),
        _ => s.parse().ok(),
    }
}

fn close(a: f64, b: f64, tolerance: Option<f64>) -> bool {
    match tolerance {
        Some(t) => (a - b).abs() <= t,
        None => a == b || (a - b).abs() <= 1e-9 * a.abs().max(b.abs()).max(1e-3),
    }
}

/// Whether `actual` is what `expected` describes.
pub fn matches(expected: &Node, actual: &Node, tolerance: Option<f64>) -> bool {
    let all = |e: &[Node], a: &[Node]| {
        e.len() == a.len() && e.iter().zip(a).all(|(e, a)| matches(e, a, tolerance))
    };
    match (expected, actual) {
        (Node::Atom(e), Node::Atom(a)) => match (number(e), number(a)) {
            (Some(x), Some(y)) => close(x, y, tolerance),
            _ => e == a,
        },
        (Node::Named(e, ei), Node::Named(a, ai)) => e == a && matches(ei, ai, tolerance),
        // `<1, 2, 3>` for `DVec3(1, 2, 3)`, `{ rgb: .. }` for `Colour { rgb: .. }`.
        (Node::Tuple(_) | Node::List(_) | Node::Struct(_), Node::Named(_, inner)) => {
            matches(expected, inner, tolerance)
        }
        (Node::Tuple(e) | Node::List(e), Node::Tuple(a) | Node::List(a)) => all(e, a),
        (Node::Struct(e), Node::Struct(a)) => e.iter().all(|(k, v)| {
            a.iter()
                .find(|(ak, _)| ak == k)
                .is_some_and(|(_, av)| matches(v, av, tolerance))
        }),
        _ => false,
    }
}

/// Three numbers from `<a, b, c>` or `DVec3(a, b, c)`.
pub fn vector(node: &Node) -> Option<[f64; 3]> {
    let items = match node {
        Node::Named(_, inner) => return vector(inner),
        Node::Tuple(items) | Node::List(items) => items,
        _ => return None,
    };
    let mut out = [0.0; 3];
    if items.len() != 3 {
        return None;
    }
    for (o, i) in out.iter_mut().zip(items) {
        let Node::Atom(a) = i else { return None };
        *o = number(a)?;
    }
    Some(out)
}

/// Applies the `DAffine3` at `affine` (a `matrix3` with axes and a `translation`) to `p`.
pub fn apply(affine: &Node, p: [f64; 3]) -> Option<[f64; 3]> {
    let get = |path: &str| follow(affine, path).ok().and_then(|n| vector(&n));
    let (x, y, z) = (
        get("matrix3.x_axis")?,
        get("matrix3.y_axis")?,
        get("matrix3.z_axis")?,
    );
    let t = get("translation")?;
    Some([0, 1, 2].map(|i| x[i] * p[0] + y[i] * p[1] + z[i] * p[2] + t[i]))
}
