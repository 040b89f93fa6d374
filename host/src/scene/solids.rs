//! Closed opaque meshes drawn single-sided, whatever their material says.
//!
//! glTF exporters often mark every material double-sided (Blender does whenever back-face culling is
//! off, its default). On a closed object, such as a column, depth peeling then takes the inside of
//! its far side as the next layer: a surface no point of the lens sees (it lies in the umbra of the
//! object's near side), which shows through the blurred silhouette where the object's background
//! belongs. From any point outside a closed, consistently wound, opaque surface its back faces are
//! hidden by its front faces, so drawing it single-sided changes no view from outside and removes
//! those layers on every path that draws the mesh (host peel, device peel, accumulation buffer).
//!
//! A connected part of the mesh (triangles sharing edges, vertices welded by position) is such a
//! **solid** when every edge is shared by exactly two of its triangles, wound in opposite
//! directions, its signed volume is positive (faces wound outwards), every material it uses is
//! opaque (alpha mode `OPAQUE`: a blended or masked surface lets its inside show), and the eye is
//! outside it. Thin cards, open shells, rooms seen from inside and inward-wound boxes stay as the
//! file says.

use std::collections::HashMap;

use dof_shaders::raster::mesh::{ALPHA_BLEND, ALPHA_MASK, DOUBLE_SIDED};
use glam::Vec3;

use super::mesh::MeshScene;

/// What [`MeshScene::single_sided_solids`] changed.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub struct SolidReport {
    /// Solids with a double-sided material, drawn single-sided.
    pub solids: u32,
    /// Their triangles.
    pub triangles: u64,
    /// Closed solids left double-sided because the eye is inside them.
    pub around_eye: u32,
}

impl std::fmt::Display for SolidReport {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        if self.solids > 0 {
            write!(
                f,
                "{} closed opaque object(s) with double-sided materials drawn single-sided ({} triangles): their inner faces \
                 are hidden from every point outside",
                self.solids, self.triangles
            )?;
        }
        if self.around_eye > 0 {
            write!(f, "{}{} closed object(s) around the eye left double-sided", if self.solids > 0 { "; " } else { "" }, self.around_eye)?;
        }
        Ok(())
    }
}

impl MeshScene {
    /// Draws single-sided every solid (module docs) seen from `eye` that has a double-sided material:
    /// its triangles take a single-sided copy of their material. Returns what changed.
    pub fn single_sided_solids(&mut self, eye: Vec3) -> SolidReport {
        let mut report = SolidReport::default();
        let n = self.triangles.len();
        // Vertices welded by position: exporters split them at seams of normals and texture
        // coordinates, which does not open the surface.
        let mut welded_ids: HashMap<[u32; 3], u32> = HashMap::new();
        let welded: Vec<u32> = self
            .vertices
            .iter()
            .map(|v| {
                let key = v.position.map(f32::to_bits);
                let next = welded_ids.len() as u32;
                *welded_ids.entry(key).or_insert(next)
            })
            .collect();
        let corners = |t: usize| [0, 1, 2].map(|k| welded[self.triangles[t][k] as usize]);
        // Directed edges and their counts; triangles joined across shared edges.
        let mut directed: HashMap<(u32, u32), u32> = HashMap::with_capacity(3 * n);
        let mut first_on_edge: HashMap<(u32, u32), usize> = HashMap::with_capacity(3 * n);
        let mut parent: Vec<usize> = (0..n).collect();
        fn root(parent: &mut [usize], mut i: usize) -> usize {
            while parent[i] != i {
                parent[i] = parent[parent[i]];
                i = parent[i];
            }
            i
        }
        for t in 0..n {
            let c = corners(t);
            for k in 0..3 {
                let (a, b) = (c[k], c[(k + 1) % 3]);
                *directed.entry((a, b)).or_insert(0) += 1;
                let undirected = (a.min(b), a.max(b));
                match first_on_edge.get(&undirected) {
                    Some(&other) => {
                        let (ra, rb) = (root(&mut parent, t), root(&mut parent, other));
                        parent[ra] = rb;
                    }
                    None => {
                        first_on_edge.insert(undirected, t);
                    }
                }
            }
        }
        // Per component: closed and consistently wound, opaque, its volume, its triangles.
        struct Part {
            closed: bool,
            opaque: bool,
            volume: f64,
            triangles: Vec<usize>,
        }
        let mut parts: HashMap<usize, Part> = HashMap::new();
        for t in 0..n {
            let r = root(&mut parent, t);
            let part = parts.entry(r).or_insert(Part { closed: true, opaque: true, volume: 0.0, triangles: Vec::new() });
            let c = corners(t);
            for k in 0..3 {
                let (a, b) = (c[k], c[(k + 1) % 3]);
                if directed.get(&(a, b)) != Some(&1) || directed.get(&(b, a)) != Some(&1) {
                    part.closed = false;
                }
            }
            let material = self.materials.get(self.triangles[t][3] as usize).map_or(0, |m| m.flags);
            part.opaque &= material & (ALPHA_BLEND | ALPHA_MASK) == 0;
            let p = [0, 1, 2].map(|k| Vec3::from(self.vertices[self.triangles[t][k] as usize].position).as_dvec3());
            part.volume += p[0].dot(p[1].cross(p[2])) / 6.0;
            part.triangles.push(t);
        }
        let mut twins: HashMap<u32, u32> = HashMap::new();
        for part in parts.values() {
            let double_sided = part
                .triangles
                .iter()
                .any(|&t| self.materials.get(self.triangles[t][3] as usize).is_some_and(|m| m.flags & DOUBLE_SIDED != 0));
            if !part.closed || !part.opaque || !(part.volume > 0.0) || !double_sided {
                continue;
            }
            if self.contains(eye, &part.triangles) {
                report.around_eye += 1;
                continue;
            }
            report.solids += 1;
            report.triangles += part.triangles.len() as u64;
            for &t in &part.triangles {
                let m = self.triangles[t][3];
                if self.materials[m as usize].flags & DOUBLE_SIDED == 0 {
                    continue;
                }
                let twin = *twins.entry(m).or_insert_with(|| {
                    let mut single = self.materials[m as usize];
                    single.flags &= !DOUBLE_SIDED;
                    self.materials.push(single);
                    (self.materials.len() - 1) as u32
                });
                self.triangles[t][3] = twin;
            }
        }
        report
    }

    /// Whether `p` lies inside the closed surface of `triangles`: a ray from it crosses the
    /// surface an odd number of times (a direction no axis-aligned model lines up with).
    fn contains(&self, p: Vec3, triangles: &[usize]) -> bool {
        let dir = Vec3::new(0.5377, 0.6118, 0.5801).normalize();
        triangles.iter().filter(|&&t| self.ray_hits(t, p, dir).is_some()).count() % 2 == 1
    }
}
