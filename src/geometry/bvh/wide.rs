//! Nodes of four: the binary tree's nodes gathered so that a ray tests four boxes with the
//! same few instructions (four single-precision lanes, SSE2's width, which the compiler
//! vectorises without target features) in a tree half as deep.

use std::mem::MaybeUninit;
use std::ops::Range;

use glam::DVec3;

use super::{Binary, BinaryNode, Bvh, f32_down, f32_up, few};
use crate::geometry::{Aabb, Ray};

pub const WIDTH: usize = 4;

/// The lane of an absent child: its box is empty, so no ray or point ever enters it.
const EMPTY: u32 = u32::MAX;

/// Four children side by side, their boxes one array per bound and axis (a lane per
/// child). 128 bytes: two cache lines.
#[derive(Clone, Copy, Debug, PartialEq)]
#[repr(C, align(64))]
pub struct Node {
    /// `bounds[0][axis]` the children's minima, `bounds[1][axis]` their maxima.
    bounds: [[[f32; WIDTH]; 3]; 2],
    /// Interior child: its node. Leaf child: its first item.
    child: [u32; WIDTH],
    /// Leaf child: its number of items (> 0). Interior child or absent lane: 0.
    count: [u16; WIDTH],
    /// Per octant of ray directions (bit a set: negative along axis a), the lanes in the
    /// order a ray of that octant meets their boxes' centres, two bits a lane, first in
    /// the low bits: a walk that wants any hit visits nearer boxes first without sorting.
    order: [u8; 8],
}

impl Node {
    const EMPTY: Node = Node {
        bounds: [[[f32::INFINITY; WIDTH]; 3], [[f32::NEG_INFINITY; WIDTH]; 3]],
        child: [EMPTY; WIDTH],
        count: [0; WIDTH],
        order: [0b11_10_01_00; 8],
    };

    fn set(&mut self, lane: usize, b: &BinaryNode, child: u32) {
        for axis in 0..3 {
            self.bounds[0][axis][lane] = b.bounds.min[axis];
            self.bounds[1][axis][lane] = b.bounds.max[axis];
        }
        self.child[lane] = child;
        self.count[lane] = b.count;
    }

    /// The lanes sorted by their boxes' centres along the octant's diagonal, empty lanes
    /// last, packed two bits a lane.
    fn lane_order(&self, octant: usize) -> u8 {
        let along = |lane: usize| -> f64 {
            if self.child[lane] == EMPTY {
                return f64::INFINITY;
            }
            (0..3)
                .map(|a| {
                    let centre =
                        f64::from(self.bounds[0][a][lane]) + f64::from(self.bounds[1][a][lane]);
                    if octant >> a & 1 == 1 {
                        -centre
                    } else {
                        centre
                    }
                })
                .sum()
        };
        let mut lanes = [0, 1, 2, 3];
        lanes.sort_by(|&a, &b| along(a).total_cmp(&along(b)));
        lanes
            .iter()
            .enumerate()
            .fold(0, |acc, (i, &lane)| acc | (lane as u8) << (2 * i))
    }

    /// The box of one lane, in double precision.
    fn lane_box(&self, lane: usize) -> Aabb {
        let corner = |b: usize| DVec3::from_array(self.bounds[b].map(|v| f64::from(v[lane])));
        Aabb {
            min: corner(0),
            max: corner(1),
        }
    }

    /// The box of the node's children together.
    fn aabb(&self) -> Aabb {
        (0..WIDTH)
            .filter(|&lane| self.child[lane] != EMPTY)
            .fold(Aabb::EMPTY, |a, lane| a.union(&self.lane_box(lane)))
    }
}

/// Most nodes a traversal's stack holds: three more per level (four children pushed, one
/// popped). The binary tree is at most 40 SAH levels and 32 median levels deep, and a node
/// of four spans at least one binary level. A walk's stack starts uninitialised, so its
/// size costs nothing.
const DEEP_STACK: usize = 3 * 72 + 1;
/// The stack of point queries in trees up to 13 levels deep (about 10^7 items), which
/// start up with less to clear.
const SHALLOW_STACK: usize = 3 * 13 + 1;

/// Gathers the binary tree into nodes of four, depth first, so the nodes a ray visits one
/// after another are mostly neighbours.
pub(super) fn collapse(tree: Binary) -> Bvh {
    let mut nodes = Vec::with_capacity(tree.nodes.len() / 3 + 1);
    let depth = if tree.nodes.is_empty() {
        0
    } else {
        add(&tree.nodes, 0, &mut nodes)
    };
    debug_assert!(
        depth * 3 < DEEP_STACK,
        "a tree deeper than the build allows"
    );
    Bvh {
        nodes,
        positions: tree.items.len(),
        items: tree.items,
        positions_are_items: false,
        depth,
        few: Vec::new(),
    }
}

/// Adds the node of four standing for binary node `b` and everything below it; returns
/// the depth below it (1 for a node whose children are all leaves).
fn add(binary: &[BinaryNode], b: usize, out: &mut Vec<Node>) -> usize {
    let index = out.len();
    out.push(Node::EMPTY);
    let (lanes, n) = children(binary, b);
    let mut node = Node::EMPTY;
    let mut depth = 1;
    for (lane, &k) in lanes[..n].iter().enumerate() {
        let child = &binary[k];
        if child.count > 0 {
            node.set(lane, child, child.offset);
        } else {
            node.set(lane, child, out.len() as u32);
            depth = depth.max(1 + add(binary, k, out));
        }
    }
    node.order = std::array::from_fn(|octant| node.lane_order(octant));
    out[index] = node;
    depth
}

/// The binary nodes that become the children of `b`'s node of four: `b`'s two, then the
/// largest interior one among them replaced by its two, until there are four or only
/// leaves. A leaf `b` (a tree of one leaf) is its own only child.
fn children(binary: &[BinaryNode], b: usize) -> ([usize; WIDTH], usize) {
    let mut lanes = [b; WIDTH];
    if binary[b].count > 0 {
        return (lanes, 1);
    }
    let split = |k: usize| (k + 1, binary[k].offset as usize);
    (lanes[0], lanes[1]) = split(b);
    let mut n = 2;
    while n < WIDTH {
        let largest = (0..n)
            .filter(|&i| binary[lanes[i]].count == 0)
            .map(|i| (binary[lanes[i]].bounds.aabb().surface_area(), i))
            .fold(None, |best: Option<(f64, usize)>, c| match best {
                Some(b) if b.0 >= c.0 => Some(b),
                _ => Some(c),
            });
        let Some((_, i)) = largest else {
            break;
        };
        (lanes[i], lanes[n]) = split(lanes[i]);
        n += 1;
    }
    (lanes, n)
}

/// Slack on a box's far distance: the slab test's three roundings (the reciprocal, the
/// difference, the product) each err by at most 2^-24, so a far distance scaled by
/// 1 + 2^-20 is never nearer than the exact one (pbrt's 1 + 2 gamma(3), rounded up).
const SLACK: f32 = 1.0 + 1.0 / 1_048_576.0;

/// A ray as the box tests need it: in single precision, the origin rounded toward each
/// slab's side so that rounding never narrows the interval. A direction component too
/// small for a single-precision reciprocal (below 3e-39) counts as zero.
struct BoxRay {
    inv: [f32; 3],
    /// Per axis: which of a node's bounds holds the near planes (1, the maxima, when the
    /// ray runs toward -axis).
    near: [usize; 3],
    near_origin: [f32; 3],
    far_origin: [f32; 3],
    /// Bit a set where the direction is negative along axis a: which of a node's lane
    /// orders to follow.
    octant: usize,
}

impl BoxRay {
    #[inline(always)]
    fn new(ray: &Ray) -> BoxRay {
        let mut r = BoxRay {
            inv: [0.0; 3],
            near: [0; 3],
            near_origin: [0.0; 3],
            far_origin: [0.0; 3],
            octant: 0,
        };
        for axis in 0..3 {
            let inv = (1.0 / ray.direction[axis]) as f32;
            let o = ray.origin[axis];
            let (down, up) = (f32_down(o), f32_up(o));
            let negative = inv < 0.0;
            r.inv[axis] = inv;
            r.near[axis] = usize::from(negative);
            r.octant |= usize::from(negative) << axis;
            (r.near_origin[axis], r.far_origin[axis]) =
                if negative { (down, up) } else { (up, down) };
        }
        r
    }

    /// Each lane's entry distance and a bit per lane whose box the ray meets in
    /// [0, t_max]. A NaN (0 x infinity, a ray in a slab's plane) is passed over by the
    /// comparisons, which keeps the test conservative.
    #[inline(always)]
    fn test(&self, node: &Node, t_max: f32) -> ([f32; WIDTH], u32) {
        let mut t0 = [0.0f32; WIDTH];
        let mut t1 = [t_max; WIDTH];
        for axis in 0..3 {
            let near = &node.bounds[self.near[axis]][axis];
            let far = &node.bounds[1 - self.near[axis]][axis];
            for lane in 0..WIDTH {
                let a = (near[lane] - self.near_origin[axis]) * self.inv[axis];
                let b = (far[lane] - self.far_origin[axis]) * self.inv[axis];
                t0[lane] = if a > t0[lane] { a } else { t0[lane] };
                t1[lane] = if b < t1[lane] { b } else { t1[lane] };
            }
        }
        let mut mask = 0;
        for lane in 0..WIDTH {
            mask |= u32::from(t0[lane] <= t1[lane] * SLACK) << lane;
        }
        (t0, mask)
    }
}

/// Slots of a walk's stack: a power of two at least [`DEEP_STACK`], so that a slot's index
/// is reduced by a mask the compiler knows is in bounds, with no check per push.
const STACK_SLOTS: usize = DEEP_STACK.next_power_of_two();

/// Subtrees waiting to be visited: each one's node, or its leaf's first item and count,
/// and its entry distance, to pass it over once a nearer hit is found. The arrays start
/// uninitialised: clearing them took 67 of a camera ray's 1,202 instructions (10^3
/// spheres, callgrind). The count of entries is the walk's own local (`top`), not a field
/// beside the arrays: there the compiler could not keep it in a register, as a store into
/// an array might have changed it, and reloaded it after every push.
struct Stack {
    entry: [MaybeUninit<u64>; STACK_SLOTS],
    t: [MaybeUninit<f32>; STACK_SLOTS],
}

impl Stack {
    #[inline(always)]
    fn new() -> Self {
        Stack {
            entry: [const { MaybeUninit::uninit() }; STACK_SLOTS],
            t: [const { MaybeUninit::uninit() }; STACK_SLOTS],
        }
    }

    #[inline(always)]
    fn push(&mut self, top: &mut usize, t: f32, child: u32, count: u16) {
        let slot = *top % STACK_SLOTS;
        self.entry[slot].write(u64::from(child) | u64::from(count) << 32);
        self.t[slot].write(t);
        *top += 1;
    }

    /// The entry distance, the child and the count of the subtree on top.
    #[inline(always)]
    fn pop(&mut self, top: &mut usize) -> Option<(f32, u32, u16)> {
        *top = top.checked_sub(1)?;
        let slot = *top % STACK_SLOTS;
        // SAFETY: every slot below `top` was written by `push`, and `top` only grows by
        // `push`, so the slot at the new `top` holds a pushed entry (the tree is shallow
        // enough that `top` stays below STACK_SLOTS: see DEEP_STACK).
        let (e, t) = unsafe { (self.entry[slot].assume_init(), self.t[slot].assume_init()) };
        Some((t, e as u32, (e >> 32) as u16))
    }
}

/// Pushes the lanes met in the node's order for the ray's octant, all but the first,
/// later ones deeper; returns the first.
#[inline(always)]
fn push_in_order(
    stack: &mut Stack,
    top: &mut usize,
    node: &Node,
    t: &[f32; WIDTH],
    mask: u32,
    octant: usize,
) -> usize {
    let order = node.order[octant];
    let mut next = usize::MAX;
    for i in (0..WIDTH).rev() {
        let lane = usize::from(order >> (2 * i) & 3);
        if mask >> lane & 1 == 1 {
            if next != usize::MAX {
                stack.push(top, t[next], node.child[next], node.count[next]);
            }
            next = lane;
        }
    }
    next
}

impl Bvh {
    /// Visits leaves whose boxes the ray enters before `t_max`. The callback gets an item
    /// and the current `t_max`, and returns a new `t_max` (shrinking it prunes farther
    /// boxes) or `None` to stop the traversal.
    ///
    /// A node's children are visited in the order its build stored for the ray's octant
    /// (by their centres along the octant's diagonal), not sorted by where the ray enters
    /// them: nearer first often enough to prune, and an order the processor predicts,
    /// where a sort's comparisons it guessed wrong cost more than the boxes it saved
    /// (2026-12-05, 10^6 spheres, one thread: camera rays 4.3 -> 5.1 M/s, shadow rays
    /// 3.3 -> 3.7 M/s against sorting; docs/large-scenes.md). The first child met is
    /// entered without a trip through the stack, and a leaf's items are visited where it
    /// is met.
    #[inline(always)]
    pub fn traverse(
        &self,
        ray: &Ray,
        mut t_max: f64,
        mut visit: impl FnMut(u32, f64) -> Option<f64>,
    ) {
        if !self.few.is_empty() {
            return self.traverse_few(ray, t_max, visit);
        }
        if self.nodes.is_empty() {
            return;
        }
        let r = BoxRay::new(ray);
        let mut stack = Stack::new();
        let mut top = 0;
        let (mut child, mut count) = (0u32, 0u16);
        // t_max in single precision, rounded up, for the box tests; and with the tests'
        // slack, for passing over subtrees entered beyond it. Updated when t_max shrinks.
        let mut reach = f32_up(t_max);
        let mut beyond = reach * SLACK;
        loop {
            if count > 0 {
                let start = child as usize;
                for k in start..start + usize::from(count) {
                    match visit(self.item(k), t_max) {
                        Some(t) if t != t_max => {
                            t_max = t;
                            reach = f32_up(t_max);
                            beyond = reach * SLACK;
                        }
                        Some(_) => {}
                        None => return,
                    }
                }
            } else {
                let node = &self.nodes[child as usize];
                let (t, mask) = r.test(node, reach);
                if mask != 0 {
                    let lane = push_in_order(&mut stack, &mut top, node, &t, mask, r.octant);
                    (child, count) = (node.child[lane], node.count[lane]);
                    continue;
                }
            }
            // The next subtree still entered before the nearest hit found so far.
            loop {
                let Some((t_entry, c, n)) = stack.pop(&mut top) else {
                    return;
                };
                if t_entry <= beyond {
                    (child, count) = (c, n);
                    break;
                }
            }
        }
    }

    /// Whether `test` holds for an item whose box holds `p` (boxes are closed); stops at
    /// the first that does. For point queries: which children of a CSG node may hold a
    /// point.
    pub fn any_containing(&self, p: DVec3, mut test: impl FnMut(u32) -> bool) -> bool {
        let p = p.to_array();
        if !self.few.is_empty() {
            // A list's boxes in turn, without the walk's stack (a small CSG node's
            // children, for each of its crossings).
            return self.few.iter().enumerate().any(|(k, b)| {
                (0..3).all(|a| b[a][0] <= p[a] && p[a] <= b[a][1]) && test(self.item(k))
            });
        }
        let holds = |node: &Node, lane: usize| {
            (0..3).all(|a| {
                f64::from(node.bounds[0][a][lane]) <= p[a]
                    && p[a] <= f64::from(node.bounds[1][a][lane])
            })
        };
        !self.walk(holds, |mut positions, _, _| {
            !positions.any(|k| test(self.item(k)))
        })
    }

    /// Visits every item whose box may meet a region: `meets` says whether a box may (it
    /// may say so of a box that does not), and `visit` gets each such item with the box it
    /// was judged by (its own in a tree walked as a list, else its leaf's) and stops the
    /// walk by returning false. Returns whether the walk ran to the end.
    pub fn each_meeting(
        &self,
        meets: impl Fn(&Aabb) -> bool,
        mut visit: impl FnMut(u32, &Aabb) -> bool,
    ) -> bool {
        if !self.few.is_empty() {
            return self.few.iter().enumerate().all(|(k, b)| {
                let own = few::own_box(b);
                !meets(&own) || visit(self.item(k), &own)
            });
        }
        let lane_meets = |node: &Node, lane: usize| meets(&node.lane_box(lane));
        let leaf = |positions: Range<usize>, node: &Node, lane: usize| {
            let lane_box = node.lane_box(lane);
            positions
                .into_iter()
                .all(|k| visit(self.item(k), &lane_box))
        };
        self.walk(lane_meets, leaf)
    }

    /// Walks the subtrees whose boxes `meets` accepts, handing each leaf met (its positions,
    /// its node and lane) to `leaf`, which stops the walk by returning false. Returns
    /// whether the walk ran to the end. Absent lanes hold empty boxes, which `meets` must
    /// refuse.
    fn walk(
        &self,
        meets: impl Fn(&Node, usize) -> bool,
        leaf: impl FnMut(Range<usize>, &Node, usize) -> bool,
    ) -> bool {
        if self.nodes.is_empty() {
            return true;
        }
        if self.depth * 3 < SHALLOW_STACK {
            // As many as a walk's stack: three more per level.
            self.walk_in::<SHALLOW_STACK>(meets, leaf)
        } else {
            self.walk_in::<DEEP_STACK>(meets, leaf)
        }
    }

    fn walk_in<const N: usize>(
        &self,
        meets: impl Fn(&Node, usize) -> bool,
        mut leaf: impl FnMut(Range<usize>, &Node, usize) -> bool,
    ) -> bool {
        let mut stack = [0u32; N];
        let mut top = 1;
        while top > 0 {
            top -= 1;
            let node = &self.nodes[stack[top] as usize];
            for lane in 0..WIDTH {
                if !meets(node, lane) {
                    continue;
                }
                let (child, count) = (node.child[lane] as usize, usize::from(node.count[lane]));
                if count == 0 {
                    stack[top] = child as u32;
                    top += 1;
                } else if !leaf(child..child + count, node, lane) {
                    return false;
                }
            }
        }
        true
    }

    /// The box around every item (empty for an empty tree).
    pub fn bounds(&self) -> Aabb {
        if !self.few.is_empty() {
            return (0..self.few.len())
                .fold(Aabb::EMPTY, |b, k| b.union(&few::own_box(&self.few[k])));
        }
        self.nodes.first().map_or(Aabb::EMPTY, Node::aabb)
    }

    /// The deepest leaf's depth in nodes of four (0 for an empty tree).
    pub fn depth(&self) -> usize {
        self.depth
    }
}

#[cfg(test)]
mod tests {
    use super::super::NodeBox;
    use super::*;

    /// Rays from random origins in random directions, at scales from tiny to astronomic:
    /// the single-precision test never misses a box the exact double-precision test meets.
    #[test]
    fn the_single_precision_test_is_conservative() {
        let mut uniform = crate::geometry::uniform_stream(0x5851_F42D_4C95_7F2Du64);
        let mut next = move || uniform() - 0.5;
        let mut met = 0;
        for scale in [1e-20, 1e-3, 1.0, 1e4, 1e9, 1e20] {
            for _ in 0..20_000 {
                let a = DVec3::new(next(), next(), next()) * scale;
                let b = a + DVec3::new(next(), next(), next()).abs() * scale * 0.1;
                let exact = Aabb::new(a, b);
                let origin = DVec3::new(next(), next(), next()) * scale * 2.0;
                // Aim near the box's corner or face so many rays graze it.
                let target = a + (b - a) * DVec3::new(next() + 0.5, next() + 0.5, 1.0);
                let mut d = target - origin;
                if next() < -0.3 {
                    d.x = 0.0;
                }
                let ray = Ray::new(origin, d);
                let t_max = if next() < 0.0 { f64::INFINITY } else { 1.0 };
                let mut node = Node::EMPTY;
                let bn = BinaryNode {
                    bounds: NodeBox::enclosing(&exact),
                    offset: 0,
                    count: 1,
                };
                node.set(0, &bn, 0);
                let (_, mask) = BoxRay::new(&ray).test(&node, f32_up(t_max));
                if exact.hit(&ray, ray.direction.recip(), t_max).is_some() {
                    met += 1;
                    assert_eq!(mask & 1, 1, "missed {exact:?} on {ray:?}");
                }
                assert_eq!(mask & !1, 0, "an empty lane was met");
            }
        }
        assert!(
            met > 10_000,
            "too few rays met their box ({met}) to test anything"
        );
    }

    /// Boxes at exponentially growing distances make the SAH build a chain as deep as its
    /// limits allow: the deepest stack is used, and a ray along the chain still meets every
    /// box, as does a point query for each.
    #[test]
    fn a_deep_tree_is_walked_whole() {
        let bounds: Vec<Aabb> = (0..300)
            .map(|i| {
                let x = 1.2f64.powi(i);
                Aabb::new(DVec3::new(x, -0.5, -0.5), DVec3::new(x * 1.1, 0.5, 0.5))
            })
            .collect();
        let bvh = Bvh::build(&bounds);
        assert!(bvh.depth() * 3 + 1 > SHALLOW_STACK, "depth {}", bvh.depth());
        let mut seen = Vec::new();
        let ray = Ray::new(DVec3::new(0.0, 0.0, 0.0), DVec3::X);
        bvh.traverse(&ray, f64::INFINITY, |i, t| {
            seen.push(i);
            Some(t)
        });
        seen.sort_unstable();
        assert_eq!(seen, (0..300).collect::<Vec<u32>>());
        for (i, b) in bounds.iter().enumerate() {
            assert!(bvh.any_containing(b.centre(), |j| j as usize == i));
        }
    }

    /// Each octant's order holds every lane once, the lanes of a node with three children
    /// sorted by their centres along the octant's diagonal and the empty lane last.
    #[test]
    fn lane_orders_follow_the_diagonals() {
        let centres = [
            DVec3::new(0.0, 0.0, 0.0),
            DVec3::new(4.0, 1.0, 0.0),
            DVec3::new(1.0, 0.0, 5.0),
        ];
        let mut node = Node::EMPTY;
        for (lane, c) in centres.iter().enumerate() {
            let b = BinaryNode {
                bounds: NodeBox::enclosing(&Aabb::new(*c - 0.5, *c + 0.5)),
                offset: 0,
                count: 1,
            };
            node.set(lane, &b, lane as u32);
        }
        for octant in 0..8 {
            let order = node.lane_order(octant);
            let lanes: Vec<usize> = (0..WIDTH)
                .map(|i| usize::from(order >> (2 * i) & 3))
                .collect();
            let mut seen = lanes.clone();
            seen.sort_unstable();
            assert_eq!(seen, [0, 1, 2, 3], "octant {octant}: {lanes:?}");
            assert_eq!(lanes[3], 3, "the empty lane is not last: {lanes:?}");
            let diagonal = DVec3::from_array(std::array::from_fn(|a| {
                if octant >> a & 1 == 1 { -1.0 } else { 1.0 }
            }));
            let along: Vec<f64> = lanes[..3]
                .iter()
                .map(|&l| centres[l].dot(diagonal))
                .collect();
            assert!(
                along.windows(2).all(|w| w[0] <= w[1]),
                "octant {octant}: {along:?}"
            );
        }
    }

    #[test]
    fn nodes_are_two_cache_lines() {
        assert_eq!(size_of::<Node>(), 128);
    }
}
