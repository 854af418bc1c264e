//! The memory budget: what the objects and values a scene makes may take, so that a loop
//! that makes too much ends in seconds with an error naming it, rather than after it has
//! exhausted the machine.
//!
//! Sizes are estimates from the types' sizes, kept as a running count: every shape made
//! (an [`Object`](crate::scene::Object)), every texture that is not shared, the scene's
//! object list as it grows (the slack of its capacity included) and array elements. Memory
//! freed again (a value replaced) is not given back, so the count errs on the high side.

use super::super::diagnostics::{Diagnostic, Span};
use super::Evaluator;
use super::stream::Cond;

/// What a shape costs the process: its place in the scene model and, once the scene is
/// prepared for rendering, its primitive and share of the BVH (the two are alive together
/// while the render-ready scene is built).
pub(super) const OBJECT_BYTES: usize =
    size_of::<crate::scene::Object>() + crate::geometry::PREPARED_BYTES_PER_PRIMITIVE;

/// Bytes the scene may take by default: the smaller of half the physical memory and the
/// process's address-space limit (`ulimit -v`); 4 GiB when neither can be read.
pub fn default_memory_budget() -> u64 {
    let half_physical = physical_memory().map(|m| m / 2);
    [half_physical, address_space_limit()]
        .into_iter()
        .flatten()
        .min()
        .unwrap_or(4 << 30)
}

/// `MemTotal` from /proc/meminfo.
fn physical_memory() -> Option<u64> {
    let text = std::fs::read_to_string("/proc/meminfo").ok()?;
    let line = text.lines().find(|l| l.starts_with("MemTotal:"))?;
    let kb: u64 = line.split_whitespace().nth(1)?.parse().ok()?;
    Some(kb * 1024)
}

/// The soft `RLIMIT_AS` from /proc/self/limits; `None` when unlimited or unreadable.
fn address_space_limit() -> Option<u64> {
    let text = std::fs::read_to_string("/proc/self/limits").ok()?;
    let line = text.lines().find(|l| l.starts_with("Max address space"))?;
    line["Max address space".len()..]
        .split_whitespace()
        .next()?
        .parse()
        .ok()
}

/// A size as written on the command line: bytes, or with a suffix K, M, G or T (powers of
/// 1024, an optional `B` or `iB` after it): `2G`, `512M`, `1.5GB`.
pub fn parse_memory_size(text: &str) -> Result<u64, String> {
    let t = text.trim();
    let t = t
        .strip_suffix("iB")
        .or_else(|| t.strip_suffix('B'))
        .unwrap_or(t);
    let (number, unit) = match t.char_indices().last() {
        Some((i, c)) if c.is_ascii_alphabetic() => (&t[..i], c.to_ascii_uppercase()),
        _ => (t, ' '),
    };
    let scale: u64 = match unit {
        ' ' => 1,
        'K' => 1 << 10,
        'M' => 1 << 20,
        'G' => 1 << 30,
        'T' => 1 << 40,
        _ => return Err(format!("`{text}` is not a size (like 2G, 512M or 1000000)")),
    };
    match number.trim().parse::<f64>() {
        Ok(n) if n.is_finite() && n > 0.0 => Ok((n * scale as f64) as u64),
        _ => Err(format!("`{text}` is not a size (like 2G, 512M or 1000000)")),
    }
}

/// `4.0 GB`, `512.0 MB`, `900 bytes` (units of 1024).
pub(super) fn format_bytes(bytes: u64) -> String {
    const UNITS: [(&str, u64); 4] = [
        ("TB", 1 << 40),
        ("GB", 1 << 30),
        ("MB", 1 << 20),
        ("KB", 1 << 10),
    ];
    for (name, size) in UNITS {
        if bytes >= size {
            return format!("{:.1} {name}", bytes as f64 / size as f64);
        }
    }
    format!("{bytes} bytes")
}

/// `48,000,000`.
fn thousands(n: u64) -> String {
    let digits = n.to_string();
    let mut out = String::new();
    for (i, c) in digits.chars().enumerate() {
        if i > 0 && (digits.len() - i).is_multiple_of(3) {
            out.push(',');
        }
        out.push(c);
    }
    out
}

/// The running count against the limit.
#[derive(Clone, Copy, Debug)]
pub(super) struct Budget {
    pub limit: u64,
    pub used: u64,
    /// Shapes and mesh triangles made so far.
    pub objects: u64,
}

impl Budget {
    pub fn new(limit: u64) -> Budget {
        Budget {
            limit,
            used: 0,
            objects: 0,
        }
    }
}

/// What grew, for the message.
#[derive(Clone, Copy)]
pub(super) enum Growth {
    Objects(u64),
    ArrayElements(usize),
}

impl Evaluator<'_> {
    /// Counts `bytes` more against the budget; past it, the error names what grew and where:
    /// the outermost loop running, else the place at `span`.
    pub(super) fn charge(
        &mut self,
        bytes: u64,
        growth: Growth,
        span: Span,
    ) -> Result<(), Diagnostic> {
        if let Growth::Objects(n) = growth {
            self.budget.objects = self.budget.objects.saturating_add(n);
        }
        self.budget.used = self.budget.used.saturating_add(bytes);
        if self.budget.used <= self.budget.limit {
            return Ok(());
        }
        let running_loop = self.conds.iter().find_map(|c| match c {
            Cond::While { span, .. } => Some(("#while", *span)),
            Cond::For { span, .. } => Some(("#for", *span)),
            _ => None,
        });
        let (at, what) = match (growth, running_loop) {
            (Growth::Objects(_), Some((word, s))) => (s, format!("made by the `{word}` loop at")),
            (Growth::Objects(_), None) => (span, "the last made at".to_string()),
            (Growth::ArrayElements(n), _) => (
                span,
                format!("an array of {} elements at", thousands(n as u64)),
            ),
        };
        let place = self
            .files
            .locate(at)
            .map(|l| format!("{}:{}:{}", l.file, l.line, l.column))
            .unwrap_or_else(|| "?".into());
        let what = match growth {
            Growth::Objects(_) => {
                format!("{} objects {what} {place}", thousands(self.budget.objects))
            }
            Growth::ArrayElements(_) => format!("{what} {place}"),
        };
        Err(self.err(
            at,
            format!(
                "the scene needs more than {} (the memory budget): {what}",
                format_bytes(self.budget.limit)
            ),
        ))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sizes_read_with_binary_suffixes() {
        assert_eq!(parse_memory_size("2G"), Ok(2 << 30));
        assert_eq!(parse_memory_size("512M"), Ok(512 << 20));
        assert_eq!(parse_memory_size("1.5GB"), Ok(3 << 29));
        assert_eq!(parse_memory_size("64KiB"), Ok(64 << 10));
        assert_eq!(parse_memory_size("1000"), Ok(1000));
        assert!(parse_memory_size("lots").is_err());
        assert!(parse_memory_size("-1G").is_err());
    }

    #[test]
    fn sizes_and_counts_print_for_people() {
        assert_eq!(format_bytes(4 << 30), "4.0 GB");
        assert_eq!(format_bytes(900), "900 bytes");
        assert_eq!(thousands(48_000_000), "48,000,000");
        assert_eq!(thousands(999), "999");
    }

    #[test]
    fn the_default_budget_is_positive() {
        assert!(default_memory_budget() > 0);
    }
}
