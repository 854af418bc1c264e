//! A bounding volume hierarchy: a binary tree built by binned SAH, then gathered into
//! nodes of four children tested side by side (`wide`), traversed front to back with a
//! fixed-size stack (no allocation per ray).

use glam::{DVec3, Vec3};

use std::cell::Cell;

use rayon::prelude::*;

use super::Aabb;

mod few;
mod wide;
pub use wide::Node;

/// Subtrees with fewer items than this on either side are built on the current thread.
const PARALLEL_MIN_ITEMS: usize = 4096;

thread_local! {
    /// Cleared by `build_sequential` on the building thread.
    static PARALLEL: Cell<bool> = const { Cell::new(true) };
}

fn parallel() -> bool {
    PARALLEL.with(|p| p.get())
}

fn items_len_parallel(left: usize, right: usize) -> bool {
    left.min(right) >= PARALLEL_MIN_ITEMS && parallel()
}

type Bins = ([Aabb; BINS], [usize; BINS]);

/// The union of the items' boxes (min and max are exact, so the parallel fold for large
/// slices gives the sequential result bit for bit).
fn fold_bounds(items: &[BuildItem], f: impl Fn(&BuildItem) -> Aabb + Sync) -> Aabb {
    if items.len() >= PARALLEL_MIN_ITEMS && parallel() {
        items
            .par_iter()
            .fold(|| Aabb::EMPTY, |a, it| a.union(&f(it)))
            .reduce(|| Aabb::EMPTY, |a, b| a.union(&b))
    } else {
        items.iter().fold(Aabb::EMPTY, |a, it| a.union(&f(it)))
    }
}

const BINS: usize = 12;
const MAX_LEAF: usize = 4;
/// Past this depth the build splits at the median, so traversal's fixed stack suffices.
const SAH_DEPTH_LIMIT: usize = 40;

/// A node of the binary tree the build makes, before [`wide::collapse`] gathers it into
/// nodes of four.
#[derive(Clone, Copy, Debug, PartialEq)]
struct BinaryNode {
    bounds: NodeBox,
    /// Leaf: first item. Interior: index of the right child.
    offset: u32,
    /// Leaf: number of items (> 0). Interior: 0.
    count: u16,
}

/// The binary tree while it is built: nodes depth first (the left child of node i is
/// node i + 1) and the items in leaf order.
#[derive(Default)]
struct Binary {
    nodes: Vec<BinaryNode>,
    items: Vec<u32>,
}

#[derive(Clone, Debug, Default, PartialEq)]
pub struct Bvh {
    /// Nodes of four children, depth first; the root is node 0.
    pub nodes: Vec<Node>,
    /// Item indices in leaf order; empty once the owner has put its items in that order
    /// ([`Bvh::items_in_leaf_order`]), when a leaf's positions are its items.
    pub items: Vec<u32>,
    /// The items are their positions in leaf order: a ray's visit to a leaf names its
    /// items without reading the list, a load that missed the cache for most leaves of a
    /// large scene.
    positions_are_items: bool,
    /// The number of positions in leaf order (items with a place in some leaf).
    positions: usize,
    /// The deepest leaf's depth in nodes, which sizes the traversal's stack.
    depth: usize,
    /// Per position, its box, in a tree of at most [`few::FEW`] items (else empty): such
    /// trees are walked as a list.
    few: Vec<few::ListBox>,
}

/// A box in single precision, rounded outward so it holds everything the double-precision
/// box held: a node is half the memory (and cache lines) of one holding an [`Aabb`], and
/// its boxes are at most an f32 rounding looser, which costs a test now and then, never a
/// missed hit.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct NodeBox {
    min: [f32; 3],
    max: [f32; 3],
}

impl NodeBox {
    pub fn enclosing(b: &Aabb) -> NodeBox {
        NodeBox {
            min: b.min.to_array().map(f32_down),
            max: b.max.to_array().map(f32_up),
        }
    }

    pub fn aabb(&self) -> Aabb {
        Aabb {
            min: DVec3::from_array(self.min.map(f64::from)),
            max: DVec3::from_array(self.max.map(f64::from)),
        }
    }
}

/// `v` in single precision, rounded down (never above `v`).
#[inline(always)]
fn f32_down(v: f64) -> f32 {
    let f = v as f32;
    if f64::from(f) > v { f.next_down() } else { f }
}

/// `v` in single precision, rounded up (never below `v`).
#[inline(always)]
fn f32_up(v: f64) -> f32 {
    let f = v as f32;
    if f64::from(f) < v { f.next_up() } else { f }
}

/// What the tree costs per item while it is built and after: the item, its index, a
/// binary node (leaves hold a few items; interior nodes about as many again) and the share
/// of a node of four (one per three binary interior nodes, or fewer).
pub const BYTES_PER_ITEM: usize =
    size_of::<BuildItem>() + size_of::<u32>() + size_of::<BinaryNode>() + size_of::<Node>() / 3;

/// An item while the tree is built: 40 bytes, so a million items take 40 MB of the
/// build's peak memory. The centre only chooses splits, so single precision serves.
struct BuildItem {
    bounds: NodeBox,
    centre: Vec3,
    index: u32,
}

impl Bvh {
    /// For owners that have stored their items in the tree's leaf order (item `k` at
    /// position `k`): drops the list, which then says nothing the positions do not.
    pub fn items_in_leaf_order(&mut self) {
        debug_assert!(self.items.iter().enumerate().all(|(k, &i)| k == i as usize));
        self.positions_are_items = true;
        self.items = Vec::new();
    }

    /// The item at position `k` in leaf order.
    #[inline(always)]
    fn item(&self, k: usize) -> u32 {
        if self.positions_are_items {
            k as u32
        } else {
            self.items[k]
        }
    }

    /// Every item, in leaf order.
    pub fn item_list(&self) -> impl Iterator<Item = u32> + '_ {
        (0..self.positions).map(|k| self.item(k))
    }

    /// Builds over items given by their bounds (finite, non-empty). Large subtrees are built
    /// in parallel; the tree is the same as a sequential build's, node for node.
    pub fn build(bounds: &[Aabb]) -> Bvh {
        Bvh::build_from(bounds.len(), |i| bounds[i])
    }

    /// [`Bvh::build`] over `n` items whose bounds `bounds_of` gives, so the caller need not
    /// hold them all in an array beside the tree's own.
    pub fn build_from(n: usize, bounds_of: impl Fn(usize) -> Aabb + Sync) -> Bvh {
        let item = |i: usize| {
            let b = bounds_of(i);
            BuildItem {
                bounds: NodeBox::enclosing(&b),
                centre: b.centre().as_vec3(),
                index: i as u32,
            }
        };
        // A small tree's items are read on this thread: handing a CSG node's three
        // children to the pool woke its threads for each of 10^5 such nodes (2 s of
        // yielding, scheduled in the kernel).
        let mut items: Vec<BuildItem> = if n >= PARALLEL_MIN_ITEMS && parallel() {
            (0..n).into_par_iter().map(item).collect()
        } else {
            (0..n).map(item).collect()
        };
        let mut tree = Binary {
            nodes: Vec::with_capacity(2 * items.len().max(1)),
            items: Vec::with_capacity(items.len()),
        };
        if !items.is_empty() {
            tree.build_node(&mut items, 0);
        }
        drop(items);
        let few = few::boxes(&tree.items, bounds_of);
        let mut bvh = Bvh {
            few,
            ..wide::collapse(tree)
        };
        // A list is walked without its nodes (a small CSG node's index held a node of
        // 128 bytes it never read).
        if !bvh.few.is_empty() {
            bvh.nodes = Vec::new();
        }
        bvh
    }

    /// The items `labels` names, with boxes `bounds_of(k)` in that order, as a list walked
    /// in that order, without a tree's build (a small CSG node's children: the build took
    /// 6,000 instructions for three); `None` for more than a list holds.
    pub fn list(labels: Vec<u32>, bounds_of: impl Fn(usize) -> Aabb) -> Option<Bvh> {
        if labels.is_empty() || labels.len() > few::FEW {
            return None;
        }
        let positions: Vec<u32> = (0..labels.len() as u32).collect();
        Some(Bvh {
            nodes: Vec::new(),
            few: few::boxes(&positions, bounds_of),
            positions: labels.len(),
            items: labels,
            positions_are_items: false,
            depth: 0,
        })
    }

    /// Whether the tree is walked as a list of its items' own boxes (so a visited item's
    /// box has been met).
    pub fn walks_as_list(&self) -> bool {
        !self.few.is_empty()
    }

    /// Builds the sequential way only (for tests and the benchmark's comparison).
    pub fn build_sequential(bounds: &[Aabb]) -> Bvh {
        PARALLEL.with(|p| p.set(false));
        let bvh = Bvh::build(bounds);
        PARALLEL.with(|p| p.set(true));
        bvh
    }
}

impl Binary {
    /// Appends another tree (built over a later part of the item list), shifting its links.
    fn append(&mut self, other: Binary) {
        let node_base = self.nodes.len() as u32;
        let item_base = self.items.len() as u32;
        self.nodes.extend(other.nodes.into_iter().map(|mut n| {
            n.offset += if n.count > 0 { item_base } else { node_base };
            n
        }));
        self.items.extend(other.items);
    }

    fn build_node(&mut self, items: &mut [BuildItem], depth: usize) -> usize {
        let bounds = fold_bounds(items, |it| it.bounds.aabb());
        let node_index = self.nodes.len();
        self.nodes.push(BinaryNode {
            // Exact: a union of boxes with single-precision corners.
            bounds: NodeBox::enclosing(&bounds),
            offset: 0,
            count: 0,
        });
        if items.len() <= MAX_LEAF {
            self.make_leaf(node_index, items);
            return node_index;
        }
        let centres = fold_bounds(items, |it| {
            let c = it.centre.as_dvec3();
            Aabb::new(c, c)
        });
        let extent = centres.max - centres.min;
        let axis = if extent.x >= extent.y && extent.x >= extent.z {
            0
        } else if extent.y >= extent.z {
            1
        } else {
            2
        };
        if extent[axis] <= 0.0 {
            // All centres coincide: no split separates them.
            if items.len() <= u16::MAX as usize {
                self.make_leaf(node_index, items);
                return node_index;
            }
        }
        let mid = if depth < SAH_DEPTH_LIMIT && extent[axis] > 0.0 {
            self.sah_split(items, axis, centres.min[axis], extent[axis], &bounds)
        } else {
            None
        };
        let mid = match mid {
            Some(SahDecision::Leaf) if items.len() <= 16 => {
                self.make_leaf(node_index, items);
                return node_index;
            }
            Some(SahDecision::Split(m)) => m,
            _ => {
                let m = items.len() / 2;
                items.select_nth_unstable_by(m, |a, b| a.centre[axis].total_cmp(&b.centre[axis]));
                m
            }
        };
        let (left, right) = items.split_at_mut(mid);
        let right_index = if items_len_parallel(left.len(), right.len()) {
            // Both halves are large: build them side by side into their own arrays and
            // splice them in the order a sequential build would have written them.
            let sub = |part: &mut [BuildItem]| {
                let mut t = Binary {
                    nodes: Vec::with_capacity(2 * part.len()),
                    items: Vec::with_capacity(part.len()),
                };
                t.build_node(part, depth + 1);
                t
            };
            let (l, r) = rayon::join(|| sub(left), || sub(right));
            self.append(l);
            let right_index = self.nodes.len();
            self.append(r);
            right_index
        } else {
            self.build_node(left, depth + 1);
            self.build_node(right, depth + 1)
        };
        self.nodes[node_index].offset = right_index as u32;
        node_index
    }

    fn make_leaf(&mut self, node_index: usize, items: &[BuildItem]) {
        self.nodes[node_index].offset = self.items.len() as u32;
        self.nodes[node_index].count = items.len() as u16;
        self.items.extend(items.iter().map(|it| it.index));
    }

    fn sah_split(
        &self,
        items: &mut [BuildItem],
        axis: usize,
        min: f64,
        extent: f64,
        bounds: &Aabb,
    ) -> Option<SahDecision> {
        let bin_of = |c: f64| (((c - min) / extent * BINS as f64) as usize).min(BINS - 1);
        // The bins are updated in place, a chunk of items at a time: passed by value per
        // item, the 700-byte accumulator's copies took most of the build.
        let bin_chunk = |chunk: &[BuildItem]| {
            let mut acc: Bins = ([Aabb::EMPTY; BINS], [0usize; BINS]);
            for it in chunk {
                let b = bin_of(f64::from(it.centre[axis]));
                acc.0[b] = acc.0[b].union(&it.bounds.aabb());
                acc.1[b] += 1;
            }
            acc
        };
        // Unions of boxes and counts are exact, so the parallel sums equal the sequential.
        let (bin_bounds, bin_count) = if items.len() >= PARALLEL_MIN_ITEMS && parallel() {
            items
                .par_chunks(PARALLEL_MIN_ITEMS)
                .map(bin_chunk)
                .reduce_with(|mut a, b| {
                    for i in 0..BINS {
                        a.0[i] = a.0[i].union(&b.0[i]);
                        a.1[i] += b.1[i];
                    }
                    a
                })
                .unwrap_or_else(|| bin_chunk(&[]))
        } else {
            bin_chunk(items)
        };
        // Cost of splitting after bin i, from prefix and suffix sweeps.
        let mut right_area = [0.0; BINS];
        let mut right_count = [0usize; BINS];
        let (mut acc, mut n) = (Aabb::EMPTY, 0);
        for i in (1..BINS).rev() {
            acc = acc.union(&bin_bounds[i]);
            n += bin_count[i];
            right_area[i] = acc.surface_area();
            right_count[i] = n;
        }
        let (mut acc, mut n) = (Aabb::EMPTY, 0);
        let mut best = (f64::INFINITY, 0);
        for i in 0..BINS - 1 {
            acc = acc.union(&bin_bounds[i]);
            n += bin_count[i];
            if n == 0 || right_count[i + 1] == 0 {
                continue;
            }
            let cost =
                acc.surface_area() * n as f64 + right_area[i + 1] * right_count[i + 1] as f64;
            if cost < best.0 {
                best = (cost, i);
            }
        }
        if !best.0.is_finite() {
            return None;
        }
        // Traversal costs about one item test per node visit.
        let leaf_cost = items.len() as f64 * bounds.surface_area();
        if best.0 + bounds.surface_area() >= leaf_cost {
            return Some(SahDecision::Leaf);
        }
        let split_bin = best.1;
        let mut left = 0;
        for i in 0..items.len() {
            if bin_of(f64::from(items[i].centre[axis])) <= split_bin {
                items.swap(i, left);
                left += 1;
            }
        }
        if left == 0 || left == items.len() {
            None
        } else {
            Some(SahDecision::Split(left))
        }
    }
}

enum SahDecision {
    Leaf,
    Split(usize),
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::geometry::Ray;

    #[test]
    fn traversal_finds_every_box_the_ray_crosses() {
        // A line of unit boxes along x; a ray along x must meet all of them.
        let bounds: Vec<Aabb> = (0..1000)
            .map(|i| {
                let x = i as f64 * 2.0;
                Aabb::new(DVec3::new(x, -0.5, -0.5), DVec3::new(x + 1.0, 0.5, 0.5))
            })
            .collect();
        let bvh = Bvh::build(&bounds);
        let mut seen = vec![false; bounds.len()];
        bvh.traverse(
            &Ray::new(DVec3::new(-1.0, 0.0, 0.0), DVec3::X),
            f64::INFINITY,
            |i, t| {
                seen[i as usize] = true;
                Some(t)
            },
        );
        assert!(seen.iter().all(|&s| s));
        let mut count = 0;
        bvh.traverse(
            &Ray::new(DVec3::new(-1.0, 2.0, 0.0), DVec3::X),
            f64::INFINITY,
            |_, t| {
                count += 1;
                Some(t)
            },
        );
        assert_eq!(count, 0);
    }

    /// Rounded to single precision, a node's box still holds the box it was made from,
    /// at coordinates from tiny to astronomic, and is no more than an f32 step looser.
    #[test]
    fn single_precision_boxes_enclose_the_double_ones() {
        let mut uniform = crate::geometry::uniform_stream(0x2545_F491_4F6C_DD1Du64);
        let mut next = move || uniform() - 0.5;
        for scale in [1e-30, 1e-3, 1.0, 1e3, 1e7, 1e30, 1e40] {
            for _ in 0..1000 {
                let a = DVec3::new(next(), next(), next()) * scale;
                let b = a + DVec3::new(next(), next(), next()).abs() * scale;
                let exact = Aabb::new(a, b);
                let single = NodeBox::enclosing(&exact).aabb();
                assert!(single.min.cmple(exact.min).all(), "{exact:?} -> {single:?}");
                assert!(single.max.cmpge(exact.max).all(), "{exact:?} -> {single:?}");
                if scale < 1e38 {
                    let slack = (exact.min.abs().max(exact.max.abs())) * 2.0f64.powi(-23);
                    assert!((exact.min - single.min).cmple(slack).all());
                    assert!((single.max - exact.max).cmple(slack).all());
                }
            }
        }
    }

    #[test]
    fn identical_boxes_do_not_overflow() {
        let bounds = vec![Aabb::new(DVec3::ZERO, DVec3::ONE); 100_000];
        let bvh = Bvh::build(&bounds);
        let mut count = 0;
        bvh.traverse(
            &Ray::new(DVec3::splat(-1.0), DVec3::ONE),
            f64::INFINITY,
            |_, t| {
                count += 1;
                Some(t)
            },
        );
        assert_eq!(count, 100_000);
    }

    /// A simple deterministic scatter of boxes of varied sizes (no random generator needed).
    fn scattered_boxes(n: usize) -> Vec<Aabb> {
        let mut next = crate::geometry::uniform_stream(0x9E37_79B9_7F4A_7C15u64);
        (0..n)
            .map(|_| {
                let c = DVec3::new(next(), next(), next()) * 100.0;
                let r = 0.01 + next() * next();
                Aabb::new(c - DVec3::splat(r), c + DVec3::splat(r))
            })
            .collect()
    }

    #[test]
    fn parallel_build_gives_the_sequential_tree() {
        let bounds = scattered_boxes(60_000);
        let parallel = Bvh::build(&bounds);
        let sequential = Bvh::build_sequential(&bounds);
        assert_eq!(parallel.nodes.len(), sequential.nodes.len());
        assert!(parallel == sequential, "the trees differ");
        // And it is deterministic run to run.
        assert!(Bvh::build(&bounds) == parallel);
        // Every item appears exactly once.
        let mut seen = parallel.items.clone();
        seen.sort_unstable();
        assert!(seen.iter().enumerate().all(|(i, &x)| i as u32 == x));
    }
}
