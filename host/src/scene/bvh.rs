//! A small bounding-volume hierarchy over a scene's bounded primitives, so rays test a few
//! primitives instead of all. Boxes are padded slightly and the slab test is conservative (a NaN
//! from `0 · inf` never rejects), so the hierarchy only ever skips primitives a ray cannot hit;
//! exact tests decide.

use glam::Vec3;

/// An axis-aligned bounding box.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Aabb {
    pub min: Vec3,
    pub max: Vec3,
}

impl Aabb {
    pub const EMPTY: Aabb = Aabb { min: Vec3::INFINITY, max: Vec3::NEG_INFINITY };

    pub fn union(self, o: Aabb) -> Aabb {
        Aabb { min: self.min.min(o.min), max: self.max.max(o.max) }
    }

    pub fn centre(&self) -> Vec3 {
        0.5 * (self.min + self.max)
    }

    /// Grown by a small absolute and relative margin, so flat boxes (quads) have thickness and
    /// rounding never drops a grazing hit.
    pub fn padded(self) -> Aabb {
        let pad = Vec3::splat(1e-4) + (self.max - self.min).abs() * 1e-4 + self.min.abs().max(self.max.abs()) * 1e-6;
        Aabb { min: self.min - pad, max: self.max + pad }
    }

    /// Entry parameter of the ray into the box within `[t_min, t_max]`, or `None`.
    #[inline]
    pub fn enter(&self, origin: Vec3, inv_dir: Vec3, t_min: f32, t_max: f32) -> Option<f32> {
        let t1 = (self.min - origin) * inv_dir;
        let t2 = (self.max - origin) * inv_dir;
        // `f32::min`/`max` return the other operand for NaN: a NaN slab constrains nothing.
        let near = t1.x.min(t2.x).max(t1.y.min(t2.y)).max(t1.z.min(t2.z)).max(t_min);
        let far = t1.x.max(t2.x).min(t1.y.max(t2.y)).min(t1.z.max(t2.z)).min(t_max);
        (near <= far).then_some(near)
    }
}

#[derive(Clone, Copy, Debug, PartialEq)]
struct Node {
    bounds: Aabb,
    /// Leaf: first index into `Bvh::items`; inner: index of the left child (the right follows it
    /// at `left + 1`).
    start: u32,
    /// Leaf: number of items; inner: 0.
    count: u32,
}

/// The hierarchy: nodes and the primitive indices their leaves cover.
#[derive(Clone, Debug, PartialEq)]
pub struct Bvh {
    nodes: Vec<Node>,
    items: Vec<u32>,
}

const LEAF: usize = 2;
const MAX_DEPTH: usize = 48;

impl Bvh {
    /// Builds over `(primitive index, bounds)` pairs by median splits on the longest axis.
    pub fn build(boxes: &[(u32, Aabb)]) -> Bvh {
        let mut bvh = Bvh { nodes: Vec::new(), items: Vec::new() };
        if boxes.is_empty() {
            return bvh;
        }
        let mut work: Vec<(u32, Aabb)> = boxes.iter().map(|&(i, b)| (i, b.padded())).collect();
        bvh.nodes.push(Node { bounds: Aabb::EMPTY, start: 0, count: 0 });
        bvh.split(0, &mut work, 0);
        bvh
    }

    fn split(&mut self, node: usize, work: &mut [(u32, Aabb)], depth: usize) {
        let bounds = work.iter().fold(Aabb::EMPTY, |acc, (_, b)| acc.union(*b));
        if work.len() <= LEAF || depth >= MAX_DEPTH {
            self.nodes[node] = Node { bounds, start: self.items.len() as u32, count: work.len() as u32 };
            self.items.extend(work.iter().map(|(i, _)| *i));
            return;
        }
        let centres = work.iter().fold(Aabb::EMPTY, |acc, (_, b)| acc.union(Aabb { min: b.centre(), max: b.centre() }));
        let extent = centres.max - centres.min;
        let axis = if extent.x >= extent.y && extent.x >= extent.z {
            0
        } else if extent.y >= extent.z {
            1
        } else {
            2
        };
        work.sort_by(|a, b| a.1.centre()[axis].total_cmp(&b.1.centre()[axis]).then(a.0.cmp(&b.0)));
        let mid = work.len() / 2;
        let left = self.nodes.len();
        self.nodes.push(Node { bounds: Aabb::EMPTY, start: 0, count: 0 });
        self.nodes.push(Node { bounds: Aabb::EMPTY, start: 0, count: 0 });
        self.nodes[node] = Node { bounds, start: left as u32, count: 0 };
        let (a, b) = work.split_at_mut(mid);
        self.split(left, a, depth + 1);
        self.split(left + 1, b, depth + 1);
    }

    /// Calls `visit(primitive)` for every primitive whose box the ray enters before `*t_max` (read
    /// again after each call, so a caller looking for the nearest hit prunes by lowering it). Nearer
    /// children are visited first.
    #[inline]
    pub fn traverse(&self, origin: Vec3, direction: Vec3, t_min: f32, t_max: &mut f32, mut visit: impl FnMut(u32, &mut f32)) {
        if self.nodes.is_empty() {
            return;
        }
        let inv = Vec3::ONE / direction;
        let mut stack = [0u32; MAX_DEPTH + 2];
        let mut top = 0usize;
        if self.nodes[0].bounds.enter(origin, inv, t_min, *t_max).is_none() {
            return;
        }
        stack[top] = 0;
        top += 1;
        while top > 0 {
            top -= 1;
            let node = self.nodes[stack[top] as usize];
            if node.count > 0 {
                for &item in &self.items[node.start as usize..(node.start + node.count) as usize] {
                    visit(item, t_max);
                }
                continue;
            }
            let (l, r) = (node.start as usize, node.start as usize + 1);
            let tl = self.nodes[l].bounds.enter(origin, inv, t_min, *t_max);
            let tr = self.nodes[r].bounds.enter(origin, inv, t_min, *t_max);
            // Push the farther child first so the nearer one is visited next.
            match (tl, tr) {
                (Some(a), Some(b)) => {
                    let (near, far) = if a <= b { (l, r) } else { (r, l) };
                    stack[top] = far as u32;
                    stack[top + 1] = near as u32;
                    top += 2;
                }
                (Some(_), None) => {
                    stack[top] = l as u32;
                    top += 1;
                }
                (None, Some(_)) => {
                    stack[top] = r as u32;
                    top += 1;
                }
                (None, None) => {}
            }
        }
    }
}
