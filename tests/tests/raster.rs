//! The mesh rasteriser: depth peeling with the umbra threshold, culling, alpha modes, the
//! accumulation buffer's sheared frustum, and Vulkan's graphics pipeline against the CPU fallback.

use dof::backend::CpuBackend;
use dof::raster::{AccumulateOptions, accumulate, peel_layers};
use dof::scene::{Camera, LayerOptions, MeshScene, Vec3};
use dof_shaders::lens::ThinLens;
use dof_shaders::raster::mesh::{ALPHA_BLEND, ALPHA_MASK, DOUBLE_SIDED, MeshMaterial, MeshVertex, NEAREST, TextureInfo, UNLIT};
use dof_tests::{assert_clean, vulkan};

/// Hand-building meshes of quads.
trait Build {
    fn material(&mut self, m: MeshMaterial) -> u32;
    fn quad(&mut self, corner: Vec3, u: Vec3, v: Vec3, material: u32);
    fn facing(&mut self, cx: f32, cy: f32, z: f32, h: f32, material: u32);
}

impl Build for MeshScene {
    fn material(&mut self, m: MeshMaterial) -> u32 {
        self.materials.push(m);
        self.materials.len() as u32 - 1
    }
    /// The quad `corner + a·u + b·v`, counter-clockwise seen from the side `u × v` points to; UV
    /// (0,0)..(1,1).
    fn quad(&mut self, corner: Vec3, u: Vec3, v: Vec3, material: u32) {
        let n = u.cross(v).normalize().to_array();
        let base = self.vertices.len() as u32;
        for (p, (tu, tv)) in [(corner, (0.0, 0.0)), (corner + u, (1.0, 0.0)), (corner + u + v, (1.0, 1.0)), (corner + v, (0.0, 1.0))] {
            self.vertices.push(MeshVertex { position: p.to_array(), u: tu, normal: n, v: tv, ..MeshVertex::default() });
        }
        self.triangles.push([base, base + 1, base + 2, material]);
        self.triangles.push([base, base + 2, base + 3, material]);
    }
    /// A square of half-size `h` facing the camera (+Z) at depth `z`, centred on `(cx, cy)`.
    fn facing(&mut self, cx: f32, cy: f32, z: f32, h: f32, material: u32) {
        self.quad(Vec3::new(cx - h, cy - h, -z), Vec3::new(2.0 * h, 0.0, 0.0), Vec3::new(0.0, 2.0 * h, 0.0), material);
    }
}

fn unlit(rgb: [f32; 3]) -> MeshMaterial {
    MeshMaterial { base: [rgb[0], rgb[1], rgb[2], 1.0], flags: UNLIT, ..MeshMaterial::default() }
}

const W: u32 = 96;
const H: u32 = 64;

fn camera() -> Camera {
    Camera::look_at(Vec3::ZERO, Vec3::new(0.0, 0.0, -1.0), 40f32.to_radians(), W, H)
}

fn lens(aperture_radius: f32, focus: f32) -> ThinLens {
    ThinLens { focal_length: 0.05, aperture_radius, focus_distance: focus, pixels_per_unit: H as f32 / 0.024 }
}

/// Far red wall at 10, green square at 5, blue square at 2 in front of the image centre.
fn stack() -> MeshScene {
    let mut m = MeshScene::default();
    let (red, green, blue) = (m.material(unlit([1.0, 0.0, 0.0])), m.material(unlit([0.0, 1.0, 0.0])), m.material(unlit([0.0, 0.0, 1.0])));
    m.facing(0.0, 0.0, 10.0, 20.0, red);
    m.facing(0.2, 0.0, 5.0, 1.0, green);
    m.facing(0.0, 0.0, 2.0, 0.2, blue);
    m
}

/// Every layer of the frame's own pixels (no disocclusion buffer, no guard band).
fn all_layers() -> LayerOptions {
    LayerOptions { disocclusion: false, guard_band: dof::scene::GuardBand::Off, ..LayerOptions::default() }
}

fn centre(image: &dof::layers::LayeredImage) -> Vec<(f32, [f32; 3])> {
    image.pixel(W / 2, H / 2).iter().map(|f| (f.depth, f.color)).collect()
}

#[test]
fn a_pinhole_keeps_only_the_nearest_surface() {
    let m = stack();
    let out = peel_layers(&mut CpuBackend::new(), &m.raster(), &camera(), &lens(0.0, 5.0), 0.01, &all_layers()).unwrap();
    // A pinhole's umbra is infinite: one layer everywhere, and the pass after it finds nothing.
    assert_eq!(out.image.without_mask.fragments, (W * H) as u64);
    assert_eq!(out.passes, 2);
    let c = centre(&out.image.layers);
    assert_eq!(c.len(), 1);
    assert!((c[0].0 - 2.0).abs() < 1e-5, "planar depth of the blue square: {}", c[0].0);
    assert_eq!(c[0].1, [0.0, 0.0, 1.0]);
}

#[test]
fn peeling_finds_every_surface_beyond_the_umbra_in_order() {
    let mut m = stack();
    // A copy of the blue square 1 mm behind it: inside its umbra, so never a layer of its own.
    let grey = m.material(unlit([0.5; 3]));
    m.facing(0.0, 0.0, 2.001, 0.2, grey);
    // Aperture radius 0.2: the umbra behind the green square (pixel footprint 0.028 at 5) ends at
    // 5.8, before the wall; a smaller aperture would (rightly) hide the wall there.
    let out = peel_layers(&mut CpuBackend::new(), &m.raster(), &camera(), &lens(0.2, 5.0), 0.01, &all_layers()).unwrap();
    let c = centre(&out.image.layers);
    let depths: Vec<f32> = c.iter().map(|f| f.0).collect();
    assert_eq!(c.len(), 4, "blue, green and red behind the centre, then the background, got depths {depths:?}");
    for (got, want) in depths.iter().zip([2.0, 5.0, 10.0, f32::INFINITY]) {
        assert!(*got == want || (got - want).abs() < 1e-4 * want, "depths {depths:?}");
    }
    // The wall's umbra ends before infinity, so the (black) background is the last layer.
    assert_eq!(c.iter().map(|f| f.1).collect::<Vec<_>>(), [[0.0, 0.0, 1.0], [0.0, 1.0, 0.0], [1.0, 0.0, 0.0], [0.0; 3]]);
    // The disocclusion buffer keeps hidden layers only near the squares' rims (a smaller aperture,
    // so the rims are a few pixels wide): the centre keeps one.
    let masked = peel_layers(
        &mut CpuBackend::new(),
        &m.raster(),
        &camera(),
        &lens(0.05, 5.0),
        0.01,
        &LayerOptions { guard_band: dof::scene::GuardBand::Off, ..LayerOptions::default() },
    )
    .unwrap();
    let stats = (masked.image.with_mask, masked.image.without_mask);
    assert!(stats.0.fragments < stats.1.fragments && stats.0.multi_layer_pixels > 0, "{stats:?}");
    assert_eq!(centre(&masked.image.layers).len(), 1);
}

#[test]
fn back_faces_are_culled_unless_double_sided() {
    for (flags, seen) in [(UNLIT, false), (UNLIT | DOUBLE_SIDED, true)] {
        let mut m = MeshScene::default();
        let mat = m.material(MeshMaterial { flags, ..unlit([1.0; 3]) });
        // Wound clockwise seen from the camera: its front faces away.
        m.quad(Vec3::new(-1.0, -1.0, -3.0), Vec3::new(0.0, 2.0, 0.0), Vec3::new(2.0, 0.0, 0.0), mat);
        let out = peel_layers(&mut CpuBackend::new(), &m.raster(), &camera(), &lens(0.0, 5.0), 0.01, &all_layers()).unwrap();
        let surfaces = centre(&out.image.layers).iter().filter(|f| f.0.is_finite()).count();
        assert_eq!(surfaces, seen as usize, "flags {flags}");
    }
}

#[test]
fn an_alpha_mask_cuts_a_hole_to_what_lies_behind() {
    let mut m = stack();
    // A 2x1 texture: left texel transparent, right opaque; nearest sampling.
    m.texels = vec![[1.0, 1.0, 1.0, 0.0], [1.0, 1.0, 1.0, 1.0]];
    m.textures = vec![TextureInfo { offset: 0, width: 2, height: 1, sampler: NEAREST }];
    let white = m.material(MeshMaterial { base_texture: 0, flags: UNLIT | ALPHA_MASK, ..unlit([1.0; 3]) });
    m.facing(0.0, 0.0, 1.0, 0.3, white);
    let out = peel_layers(&mut CpuBackend::new(), &m.raster(), &camera(), &lens(0.0, 5.0), 0.01, &all_layers()).unwrap();
    let at = |x: u32| out.image.layers.pixel(x, H / 2)[0];
    // Left of centre the mask is transparent: the blue square at 2 shows; right, the white square.
    assert!((at(W / 2 - 3).depth - 2.0).abs() < 1e-4, "{:?}", at(W / 2 - 3));
    assert!((at(W / 2 + 3).depth - 1.0).abs() < 1e-4, "{:?}", at(W / 2 + 3));
}

#[test]
fn the_accumulation_buffer_keeps_the_focus_plane_sharp_and_blurs_the_rest() {
    let m = stack();
    let cam = camera();
    let pinhole =
        peel_layers(&mut CpuBackend::new(), &m.raster(), &cam, &lens(0.0, 5.0), 0.01, &all_layers()).unwrap().image.layers.front().0;
    let options = AccumulateOptions { samples: 64, ..AccumulateOptions::default() };
    let acc = accumulate(&mut CpuBackend::new(), &m.raster(), &cam, &lens(0.1, 5.0), 0.01, &options).unwrap().image;
    // The green square's right half lies on the focus plane, far from any other edge: as sharp as the pinhole's.
    let green_right_edge = (W as f32 * 0.5 * (1.0 + 1.2 / (5.0 * (20f32.to_radians().tan()) * W as f32 / H as f32))) as u32;
    for x in [green_right_edge - 3, green_right_edge + 3] {
        let (a, p) = (acc.get(x, H / 2), pinhole.get(x, H / 2));
        assert!((0..3).all(|k| (a[k] - p[k]).abs() < 0.02), "x {x}: accumulated {a:?}, pinhole {p:?}");
    }
    // The blue square at 2 is out of focus (CoC radius ~2.6 px): its centre stays blue, and the
    // pixel just outside its right edge (x = 56.8 px) takes part of it.
    assert_eq!(acc.get(W / 2, H / 2), [0.0, 0.0, 1.0]);
    let rim = acc.get(57, H / 2);
    assert!(pinhole.get(57, H / 2)[2] == 0.0 && rim[2] > 0.05 && rim[2] < 0.95, "just outside the defocused square: {rim:?}");
    let total = |img: &dof::layers::RgbImage| img.data.iter().flatten().map(|&v| v as f64).sum::<f64>();
    assert!((total(&acc) - total(&pinhole)).abs() < 0.02 * total(&pinhole));
}

#[test]
fn bad_views_are_refused() {
    let m = stack();
    let mut cpu = CpuBackend::new();
    let bad_near = peel_layers(&mut cpu, &m.raster(), &camera(), &lens(0.0, 5.0), 0.0, &all_layers());
    assert!(bad_near.is_err());
    let bad_lens = peel_layers(&mut cpu, &m.raster(), &camera(), &ThinLens { focal_length: 6.0, ..lens(0.0, 5.0) }, 0.01, &all_layers());
    assert!(bad_lens.is_err());
    let zero = accumulate(&mut cpu, &m.raster(), &camera(), &lens(0.1, 5.0), 0.01, &AccumulateOptions { samples: 0, ..Default::default() });
    assert!(zero.is_err());
    let mut broken = stack();
    broken.triangles[0][1] = 999;
    let err = peel_layers(&mut cpu, &broken.raster(), &camera(), &lens(0.0, 5.0), 0.01, &all_layers()).err().unwrap();
    assert!(err.to_string().contains("names vertex"), "{err}");
}

#[test]
fn vulkan_rasterises_like_the_cpu() {
    let Some(mut vk) = vulkan() else { return };
    let mut m = stack();
    // A tilted quad (perspective-correct interpolation) and one crossing the near plane.
    let tex = m.material(MeshMaterial { base_texture: 0, flags: DOUBLE_SIDED, ..MeshMaterial::default() });
    m.texels = vec![[1.0, 0.2, 0.2, 1.0], [0.2, 1.0, 0.2, 1.0], [0.2, 0.2, 1.0, 1.0], [1.0, 1.0, 0.2, 1.0]];
    m.textures = vec![TextureInfo { offset: 0, width: 2, height: 2, sampler: 0 }];
    m.quad(Vec3::new(-2.0, -1.5, -1.0), Vec3::new(1.5, 0.0, -6.0), Vec3::new(0.0, 1.0, 0.0), tex);
    m.quad(Vec3::new(0.5, 0.6, 1.0), Vec3::new(0.0, 0.0, -4.0), Vec3::new(0.8, 0.0, 0.0), tex);
    let (cam, l) = (camera(), lens(0.08, 5.0));
    let cpu = peel_layers(&mut CpuBackend::new(), &m.raster(), &cam, &l, 0.01, &all_layers()).unwrap();
    let gpu = peel_layers(&mut vk, &m.raster(), &cam, &l, 0.01, &all_layers()).unwrap();
    assert_clean(&mut vk);
    let (a, b) = (&cpu.image.layers, &gpu.image.layers);
    let mut differing = 0;
    for p in 0..a.counts.len() {
        let (x, y) = ((p as u32) % W, (p as u32) / W);
        let (fa, fb) = (a.pixel(x, y), b.pixel(x, y));
        if fa.len() != fb.len()
            || fa
                .iter()
                .zip(fb)
                .any(|(f, g)| (f.depth - g.depth).abs() > 1e-4 * f.depth || (0..3).any(|k| (f.color[k] - g.color[k]).abs() > 1e-3))
        {
            differing += 1;
        }
    }
    // Pixel centres exactly on an edge may be given to either neighbour: a handful may differ.
    assert!(differing * 200 < a.counts.len(), "{differing} of {} pixels differ between the CPU and Vulkan", a.counts.len());
    assert!(cpu.image.without_mask.multi_layer_pixels > 500, "{:?}", cpu.image.without_mask);

    let options = AccumulateOptions { samples: 16, ..AccumulateOptions::default() };
    let acc_cpu = accumulate(&mut CpuBackend::new(), &m.raster(), &cam, &l, 0.01, &options).unwrap().image;
    let acc_gpu = accumulate(&mut vk, &m.raster(), &cam, &l, 0.01, &options).unwrap().image;
    assert_clean(&mut vk);
    let mean_diff = acc_cpu.data.iter().flatten().zip(acc_gpu.data.iter().flatten()).map(|(a, b)| (a - b).abs() as f64).sum::<f64>()
        / (3 * W * H) as f64;
    assert!(mean_diff < 2e-3, "mean |CPU - Vulkan| of the accumulation buffer: {mean_diff}");
}

/// Stiff geometry, each with its stated behaviour, on the CPU rasteriser and on Vulkan alike:
/// - a triangle wholly behind the eye draws nothing;
/// - a floor reaching behind the eye (corners behind the near plane) covers exactly the pixels
///   below the horizon, at the analytic planar depth `h / (tan(yfov/2) · ndc_y)` within 1e-4;
/// - a zero-area triangle draws nothing and yields no NaN;
/// - a triangle a thousandth of a pixel wide draws at most the one pixel whose centre it covers
///   (the CPU draws it; Vulkan's sub-pixel snapping may drop it);
/// - a triangle 10^4 units away lands at its depth within 1e-4 relative.
#[test]
fn stiff_geometry_rasterises_as_stated() {
    let mut m = MeshScene::default();
    let white = m.material(MeshMaterial { flags: UNLIT | DOUBLE_SIDED, ..unlit([1.0; 3]) });
    // Behind the eye.
    m.quad(Vec3::new(-1.0, -1.0, 2.0), Vec3::new(2.0, 0.0, 0.0), Vec3::new(0.0, 2.0, 0.0), white);
    // The floor, 1 unit below the eye, from 100 behind to 1000 ahead.
    m.quad(Vec3::new(-1000.0, -1.0, 100.0), Vec3::new(2000.0, 0.0, 0.0), Vec3::new(0.0, 0.0, -1100.0), white);
    // Zero area: three corners on one line.
    let base = m.vertices.len() as u32;
    for x in [0.0, 0.5, 1.0] {
        m.vertices.push(MeshVertex { position: [x, 0.2, -3.0], ..MeshVertex::default() });
    }
    m.triangles.push([base, base + 1, base + 2, white]);
    // A sliver a thousandth of a pixel wide around the centre of pixel (10, 10), above the horizon.
    let frame = camera().frame().unwrap();
    let dir = frame.direction(10.5, 10.5);
    let z = 5.0;
    let px = 2.0 * z * frame.tan_half_fov / H as f32;
    let c = dir * z;
    m.quad(c - Vec3::new(0.0005 * px, 0.3 * px, 0.0), Vec3::new(0.001 * px, 0.0, 0.0), Vec3::new(0.0, 0.6 * px, 0.0), white);
    // Far away: a square of 10^4 units' depth filling the top-right corner.
    m.facing(4000.0, 2800.0, 1e4, 3000.0, white);

    let run = |b: &mut dyn dof::backend::Backend| {
        peel_layers(b, &m.raster(), &camera(), &lens(0.0, 5.0), 0.01, &all_layers()).unwrap().image.layers
    };
    let mut outputs = vec![("cpu", run(&mut CpuBackend::new()))];
    if let Some(mut vk) = vulkan() {
        outputs.push(("vulkan", run(&mut vk)));
        assert_clean(&mut vk);
    }
    for (name, image) in &outputs {
        assert!(image.fragments.iter().all(|f| f.color.iter().all(|c| c.is_finite())), "{name}: NaN colour");
        for y in 0..H {
            let ndc_y = 2.0 * (y as f32 + 0.5) / H as f32 - 1.0;
            for x in 0..W {
                // The nearest surface (the background, at +inf, is no surface).
                let front = image.pixel(x, y).first().map(|f| f.depth).filter(|d| d.is_finite());
                if ndc_y > 0.0 {
                    let want = 1.0 / (frame.tan_half_fov * ndc_y);
                    let got = front.unwrap_or_else(|| panic!("{name}: floor missing at ({x}, {y})"));
                    assert!((got - want).abs() <= 1e-4 * want, "{name}: floor depth {got} at ({x}, {y}), want {want}");
                } else if (x, y) == (10, 10) {
                    // The CPU covers the centre; a GPU's sub-pixel snapping may collapse the sliver.
                    assert!(front.is_none_or(|d| (d - z).abs() < 1e-3), "{name}: the sliver's pixel: {front:?}");
                    assert!(*name != "cpu" || front.is_some(), "the CPU rasteriser covers the sliver's pixel centre");
                } else if x as f32 > 0.75 * W as f32 && (y as f32) < 0.2 * H as f32 {
                    let d = front.unwrap_or_else(|| panic!("{name}: far square missing at ({x}, {y})"));
                    assert!((d - 1e4).abs() <= 1e-4 * 1e4, "{name}: far square at depth {d}");
                } else {
                    assert!(front.is_none_or(|d| d > 1e3), "{name}: ({x}, {y}) above the horizon drew depth {front:?}");
                }
            }
        }
    }
}

/// A cube of half-size `h` centred on `c`, every face wound outwards (its vertices split per face,
/// as exporters write them).
fn cube(m: &mut MeshScene, c: Vec3, h: f32, material: u32) {
    let (x, y, z) = (Vec3::X * 2.0 * h, Vec3::Y * 2.0 * h, Vec3::Z * 2.0 * h);
    m.quad(c + Vec3::new(-h, -h, h), x, y, material);
    m.quad(c + Vec3::new(h, -h, -h), -x, y, material);
    m.quad(c + Vec3::new(h, -h, h), -z, y, material);
    m.quad(c + Vec3::new(-h, -h, -h), z, y, material);
    m.quad(c + Vec3::new(-h, h, h), x, -z, material);
    m.quad(c + Vec3::new(-h, -h, -h), x, z, material);
}

#[test]
fn closed_double_sided_objects_peel_as_single_sided_ones_and_cards_keep_both_sides() {
    let build = |cube_flags: u32| {
        let mut m = MeshScene::default();
        let wall = m.material(unlit([0.2, 0.3, 0.9]));
        let solid = m.material(MeshMaterial { flags: UNLIT | cube_flags, ..unlit([1.0, 0.2, 0.1]) });
        let card = m.material(MeshMaterial { flags: UNLIT | DOUBLE_SIDED, ..unlit([0.1, 1.0, 0.1]) });
        m.facing(0.0, 0.0, 10.0, 20.0, wall);
        cube(&mut m, Vec3::new(0.0, 0.0, -4.0), 0.5, solid);
        // A thin card seen from behind (wound clockwise from the camera), right of the cube.
        m.quad(Vec3::new(0.8, -0.25, -3.0), Vec3::new(0.0, 0.5, 0.0), Vec3::new(0.5, 0.0, 0.0), card);
        m
    };
    // An aperture wide enough that the cube's far side lies beyond its near side's umbra.
    let peel = |m: &MeshScene| {
        peel_layers(&mut CpuBackend::new(), &m.raster(), &camera(), &lens(0.5, 10.0), 0.01, &all_layers()).unwrap().image.layers
    };
    let single = peel(&build(0));
    let mut double = build(DOUBLE_SIDED);
    let as_authored = peel(&double);
    let report = double.single_sided_solids(camera().eye);
    assert_eq!((report.solids, report.triangles, report.around_eye), (1, 12, 0), "{report}");
    let fixed = peel(&double);
    assert_eq!(fixed.counts, single.counts);
    assert_eq!(fixed.fragments, single.fragments, "drawn as if authored single-sided");
    // As authored, the inside of the cube's far side (depth 4.5) was a layer behind its near side.
    let inner = |l: &dof::layers::LayeredImage| l.pixel(W / 2, H / 2).iter().filter(|f| (f.depth - 4.5).abs() < 1e-3).count();
    assert_eq!((inner(&as_authored), inner(&fixed)), (1, 0));
    // The card still shows its back.
    let card = fixed.pixel(78, H / 2);
    assert!((card[0].depth - 3.0).abs() < 1e-3 && card[0].color == [0.1, 1.0, 0.1], "{card:?}");
    // From inside the cube nothing changes.
    let mut inside = build(DOUBLE_SIDED);
    let report = inside.single_sided_solids(Vec3::new(0.0, 0.0, -4.0));
    assert_eq!((report.solids, report.around_eye), (0, 1));
    assert_eq!(inside, build(DOUBLE_SIDED));
}

#[test]
fn a_translucent_stack_deeper_than_the_layers_is_counted() {
    let mut m = MeshScene::default();
    let wall = m.material(unlit([1.0, 1.0, 1.0]));
    m.facing(0.0, 0.0, 10.0, 20.0, wall);
    let pane = m.material(MeshMaterial { flags: UNLIT | dof_shaders::raster::mesh::ALPHA_BLEND, ..unlit([1.0, 0.0, 0.0]) });
    for k in 0..8 {
        m.materials[pane as usize].base[3] = 0.1;
        m.facing(0.0, 0.0, 2.0 + 0.5 * k as f32, 1.0, pane);
    }
    let peel = |layers: u32| {
        let options = LayerOptions { max_layers: layers, translucent_passes: 0, ..all_layers() };
        peel_layers(&mut CpuBackend::new(), &m.raster(), &camera(), &lens(0.5, 10.0), 0.01, &options).unwrap().image.layers
    };
    let shallow = peel(4);
    assert!(shallow.full_and_translucent() > 0, "four of eight panes, and nothing behind them");
    assert!(shallow.ends_translucent(shallow.pixel_index(W / 2, H / 2)));
    assert_eq!(peel(16).full_and_translucent(), 0, "every pane and the wall behind them");
}

/// A scene built as real assets are: open sky above, a wall below, a poster lying on the wall
/// (the same plane: an exact depth tie, as decals and coplanar faces have), and near bars across
/// both. Returns the mesh, its camera (320x240), and the poster's colour.
fn ties() -> (MeshScene, Camera, [f32; 3]) {
    let mut m = MeshScene::default();
    let poster = [0.9, 0.8, 0.1];
    let (wall, post, bar) = (m.material(unlit([0.3, 0.4, 0.8])), m.material(unlit(poster)), m.material(unlit([0.8, 0.2, 0.1])));
    m.quad(Vec3::new(-20.0, -20.0, -10.0), Vec3::new(40.0, 0.0, 0.0), Vec3::new(0.0, 19.0, 0.0), wall);
    m.quad(Vec3::new(-2.5, -3.0, -10.0), Vec3::new(4.0, 0.0, 0.0), Vec3::new(0.0, 2.5, 0.0), post);
    for i in -4..=4 {
        m.quad(Vec3::new(0.23 * i as f32, -1.0, -2.0), Vec3::new(0.05, 0.0, 0.0), Vec3::new(0.0, 2.0, 0.0), bar);
    }
    (m, Camera::look_at(Vec3::ZERO, Vec3::new(0.0, 0.0, -1.0), 40f32.to_radians(), 320, 240), poster)
}

/// Vulkan's graphics pipeline and the CPU rasteriser (the draws' compute fallback) on a scene with
/// an exact depth tie, the tolerance stated: away from the tie, at most 1 pixel in 200 has other
/// layers (pixel centres on an edge may go to either triangle); on the tie, each rasteriser's
/// rounding of the two planes' depths picks the surface, so a pixel may show the wall on one and
/// the poster on the other, but at the same depth (within 1e-5 relative) and with one of the two
/// colours. Vulkan through the compute fallback (`DrawPath::Compute`) gives the CPU's layers bit
/// for bit, ties included.
#[test]
fn graphics_draws_agree_with_the_cpu_except_on_exact_depth_ties() {
    use dof::backend::{DrawPath, VulkanOptions};
    let Some(mut vk) = vulkan() else { return };
    let (m, cam, poster) = ties();
    let l = ThinLens { focal_length: 0.05, aperture_radius: 0.0, focus_distance: 5.0, pixels_per_unit: 240.0 / 0.024 };
    let cpu = peel_layers(&mut CpuBackend::new(), &m.raster(), &cam, &l, 0.01, &all_layers()).unwrap();
    let gpu = peel_layers(&mut vk, &m.raster(), &cam, &l, 0.01, &all_layers()).unwrap();
    assert_clean(&mut vk);
    let (a, b) = (&cpu.image.layers, &gpu.image.layers);
    // Depths equal within `rel` (the sky, at +inf, equal to itself).
    let near = |a: f32, b: f32, rel: f32| a == b || (a - b).abs() <= rel * a;
    // The pixels where either shows the poster: the tie region.
    let on_poster = |x: u32, y: u32| a.pixel(x, y).iter().chain(b.pixel(x, y)).any(|f| f.color == poster);
    let (mut away, mut away_differ, mut tie, mut tie_flipped) = (0, 0, 0, 0);
    for y in 0..a.height {
        for x in 0..a.width {
            let (fa, fb) = (a.pixel(x, y), b.pixel(x, y));
            let same = fa.len() == fb.len()
                && fa.iter().zip(fb).all(|(f, g)| near(f.depth, g.depth, 1e-4) && (0..3).all(|k| (f.color[k] - g.color[k]).abs() <= 1e-3));
            if on_poster(x, y) {
                tie += 1;
                tie_flipped += !same as u32;
                assert_eq!(fa.len(), fb.len(), "({x}, {y}) on the tie");
                for (f, g) in fa.iter().zip(fb) {
                    assert!(near(f.depth, g.depth, 1e-5), "({x}, {y}): depths {} and {}", f.depth, g.depth);
                }
            } else {
                away += 1;
                away_differ += !same as u32;
            }
        }
    }
    eprintln!("away from the tie: {away_differ} of {away} pixels differ; on the tie: {tie_flipped} of {tie} show the other surface");
    assert!(tie > 1000 && away > 10000, "{tie} {away}");
    assert!(away_differ * 200 <= away, "{away_differ} of {away} pixels away from the tie differ");

    let Some(mut compute) = dof_tests::vulkan_with(VulkanOptions { validation: true, draws: DrawPath::Compute, ..Default::default() })
    else {
        return;
    };
    let exact = peel_layers(&mut compute, &m.raster(), &cam, &l, 0.01, &all_layers()).unwrap();
    assert_clean(&mut compute);
    assert!(exact.image.layers == cpu.image.layers, "compute draws on Vulkan differ from the CPU rasteriser");
}

/// An `n` x `n` checker of single texels, 0 and 1.
fn checker(n: u32) -> Vec<[f32; 4]> {
    (0..n * n)
        .map(|i| {
            let v = ((i % n + i / n) % 2) as f32;
            [v, v, v, 1.0]
        })
        .collect()
}

/// A minified texture is filtered over each pixel's footprint: a checker of single texels many
/// to a pixel reads as its mean, seen face on and on a floor running to the horizon (a long,
/// sheared footprint), on the CPU and on Vulkan. Point-sampled, it would alias to anything from 0
/// to 1.
#[test]
fn minified_textures_read_as_the_mean_of_their_footprint() {
    let one_sample = LayerOptions { subsamples: 1, ..all_layers() };
    let mut backends: Vec<(&str, Box<dyn dof::backend::Backend>)> = vec![("cpu", Box::new(CpuBackend::new()))];
    if let Some(vk) = vulkan() {
        backends.push(("vulkan", Box::new(vk)));
    }
    for (floor, n) in [(false, 256), (true, 1024)] {
        let mut m = MeshScene {
            texels: checker(n),
            textures: vec![TextureInfo { offset: 0, width: n, height: n, sampler: 0 }],
            ..MeshScene::default()
        };
        let mat = m.material(MeshMaterial { base_texture: 0, flags: UNLIT | DOUBLE_SIDED, ..unlit([1.0; 3]) });
        if floor {
            // 1 below the eye, from 1.5 to 31.5 away: 1.5 to 6 texels a pixel across it, more along it.
            m.quad(Vec3::new(-4.0, -1.0, -1.5), Vec3::new(8.0, 0.0, 0.0), Vec3::new(0.0, 0.0, -30.0), mat);
        } else {
            // About 35 pixels across: 7.3 texels a pixel.
            m.facing(0.0, 0.0, 2.0, 0.4, mat);
        }
        for (name, backend) in backends.iter_mut() {
            let out = peel_layers(backend.as_mut(), &m.raster(), &camera(), &lens(0.0, 5.0), 0.01, &one_sample).unwrap();
            let (image, depth) = out.image.layers.front();
            let mut checked = 0;
            for y in 1..H - 1 {
                for x in 1..W - 1 {
                    // Pixels whose neighbours are all on the surface (no edge), at least 4 texels a
                    // pixel on the floor (from 4 away, short of its far edge).
                    let inside = (0..9).all(|k| depth[((y + k / 3 - 1) * W + x + k % 3 - 1) as usize].is_finite());
                    let d = depth[(y * W + x) as usize];
                    if !inside || (floor && !(4.0..25.0).contains(&d)) {
                        continue;
                    }
                    let v = image.get(x, y);
                    // A box over `L` by `L` texels of the checker is within `1 / (2 L²)` of its mean (an
                    // odd count of cells); point-sampled, a pixel could read 0 or 1.
                    assert!(v.iter().all(|c| (c - 0.5).abs() < 0.03), "{name}, floor {floor}: ({x}, {y}) at depth {d} reads {v:?}");
                    checked += 1;
                }
            }
            assert!(checked > if floor { 1000 } else { 700 }, "{name}, floor {floor}: {checked} pixels checked");
        }
    }
}

/// Magnified, a texture reads as its texels, nearest or bilinear as its sampler says.
#[test]
fn magnified_textures_keep_their_texels() {
    let one_sample = LayerOptions { subsamples: 1, ..all_layers() };
    for (sampler, expect_between) in [(NEAREST, false), (0, true)] {
        let mut m = MeshScene {
            texels: checker(2),
            textures: vec![TextureInfo { offset: 0, width: 2, height: 2, sampler }],
            ..MeshScene::default()
        };
        let mat = m.material(MeshMaterial { base_texture: 0, flags: UNLIT, ..unlit([1.0; 3]) });
        m.facing(0.0, 0.0, 2.0, 0.4, mat);
        let out = peel_layers(&mut CpuBackend::new(), &m.raster(), &camera(), &lens(0.0, 5.0), 0.01, &one_sample).unwrap();
        let (image, depth) = out.image.layers.front();
        let values: Vec<f32> = (0..W * H).filter(|&p| depth[p as usize].is_finite()).map(|p| image.get(p % W, p / W)[0]).collect();
        let between = values.iter().filter(|&&v| v > 0.01 && v < 0.99).count();
        let (lo, hi) = values.iter().fold((1.0f32, 0.0f32), |(lo, hi), &v| (lo.min(v), hi.max(v)));
        assert!(values.len() > 1000 && lo < 0.05 && hi > 0.95, "{} pixels from {lo} to {hi}", values.len());
        assert_eq!(between > 100, expect_between, "sampler {sampler}: {between} of {} pixels between the texels", values.len());
    }
}

/// Vertex colours multiply the base colour, and their alpha the coverage of a blended surface.
#[test]
fn vertex_colours_multiply_the_base_colour() {
    let one_sample = LayerOptions { subsamples: 1, ..all_layers() };
    // An opaque square tinted (0.5, 0.25, 1): 0.8 times that. A blended one of vertex alpha 0.5
    // over the wall of 0.2: half of 0.8 and half of 0.2.
    for (flags, rgba, expected) in [(UNLIT, [0.5, 0.25, 1.0, 1.0], [0.4, 0.2, 0.8]), (UNLIT | ALPHA_BLEND, [1.0, 1.0, 1.0, 0.5], [0.5; 3])]
    {
        let mut m = MeshScene::default();
        let wall = m.material(unlit([0.2; 3]));
        m.facing(0.0, 0.0, 4.0, 2.0, wall);
        let tinted = m.material(MeshMaterial { flags, ..unlit([0.8; 3]) });
        m.facing(0.0, 0.0, 2.0, 0.3, tinted);
        let first = m.vertices.len() - 4;
        for v in &mut m.vertices[first..] {
            v.color = dof::scene::mesh::pack_halves(rgba);
        }
        let out = peel_layers(&mut CpuBackend::new(), &m.raster(), &camera(), &lens(0.0, 5.0), 0.01, &one_sample).unwrap();
        let c = out.image.layers.front().0.get(W / 2, H / 2);
        assert!((0..3).all(|k| (c[k] - expected[k]).abs() < 1e-3), "flags {flags}: {c:?}, expected {expected:?}");
        let front = out.image.layers.pixel(W / 2, H / 2)[0];
        assert!((front.alpha - rgba[3]).abs() < 1e-3 && (front.depth - 2.0).abs() < 1e-3, "{front:?}");
    }
}

/// `LayerOptions::texture_probes` bounds the probes a minified lookup takes: on a noisy texture
/// running to the horizon, one probe (a trilinear lookup), 16 and the default 64 give three
/// different images, 64 the default's; outside 1 to 64 the peel is refused.
#[test]
fn the_texture_probe_budget_is_honoured() {
    let one_sample = LayerOptions { subsamples: 1, ..all_layers() };
    let n = 512;
    let noise = (0..n * n)
        .map(|i: u32| {
            let v = (dof::stress::hash(i) % 1000) as f32 / 1000.0;
            [v, v, v, 1.0]
        })
        .collect();
    let mut m =
        MeshScene { texels: noise, textures: vec![TextureInfo { offset: 0, width: n, height: n, sampler: 0 }], ..MeshScene::default() };
    let mat = m.material(MeshMaterial { base_texture: 0, flags: UNLIT | DOUBLE_SIDED, ..unlit([1.0; 3]) });
    m.quad(Vec3::new(-4.0, -1.0, -1.5), Vec3::new(8.0, 0.0, 0.0), Vec3::new(0.0, 0.0, -30.0), mat);
    let front = |probes: u32| {
        let options = LayerOptions { texture_probes: probes, ..one_sample };
        let out = peel_layers(&mut CpuBackend::new(), &m.raster(), &camera(), &lens(0.0, 5.0), 0.01, &options).unwrap();
        out.image.layers.front().0.data
    };
    let (one, sixteen, full) = (front(1), front(16), front(64));
    assert!(one != sixteen && sixteen != full && one != full);
    let default = peel_layers(&mut CpuBackend::new(), &m.raster(), &camera(), &lens(0.0, 5.0), 0.01, &one_sample).unwrap();
    assert!(default.image.layers.front().0.data == full);
    for probes in [0, 65] {
        let options = LayerOptions { texture_probes: probes, ..one_sample };
        let Err(e) = peel_layers(&mut CpuBackend::new(), &m.raster(), &camera(), &lens(0.0, 5.0), 0.01, &options) else {
            panic!("{probes} probes accepted")
        };
        let e = e.to_string();
        assert!(e.contains("probes"), "{e}");
    }
}
