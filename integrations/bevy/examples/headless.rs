//! The plugin in a headless Bevy app, checked: five cameras see the same scene of unlit panels (a
//! far wall, a pane at the focus distance, a near bar; drawn with the peel material) into linear
//! RGBA16F images of their own. One has no depth of field; one a [`LensBlur`] closed down to a
//! pinhole; one a [`LensBlur`] at f/1 on a 36 mm sensor; the next two the same two lenses with
//! four layers, peeled by Bevy's passes; and the last two, through distance fog, none and the
//! peeled pinhole. After a few frames their images are read back, and the app fails unless:
//! - the pinhole through the library equals the camera without it, bit for bit (the library reads
//!   the HDR image and writes it back exactly when nothing is blurred), and so does the peeled
//!   pinhole (its front layer, within one RGBA16F step), through fog as well (the pass cameras
//!   draw the front layers with the camera's fog);
//! - the blurred images differ from the pinhole where the near bar and the panels' edges are out
//!   of focus, and equal it in the middle of the pane in focus;
//! - the peeled blur differs from the single-layer one behind the near bar's edges, where the
//!   peel finds the pane and the wall the bar hides;
//! - every pixel is finite.
//!
//! Then every target is resized to 384x256 (the peeled cameras' passes are made again) and the
//! same checks run on the images read back at that size.
//!
//! It writes the first images as EXR into `out/`, and the scene and camera as glTF
//! (`out/bevy-scene.gltf`), so that `dof render` can render the same view (`compare.sh` does, and
//! measures the PSNR of Bevy's blurred frame against it).
//!
//! `cargo run --example headless` (from integrations/bevy).

use bevy::app::ScheduleRunnerPlugin;
use bevy::camera::RenderTarget;
use bevy::prelude::*;
use bevy::render::gpu_readback::{Readback, ReadbackComplete};
use bevy::render::render_resource::{TextureFormat, TextureUsages};
use bevy::window::ExitCondition;
use bevy_dof::{LensBlur, LensBlurPlugin, PeelMaterial, peel_material};
use dof_core::dof_shaders::half::f16_to_f32;
use std::sync::{Arc, Mutex};
use std::time::Duration;

const WIDTH: u32 = 512;
const HEIGHT: u32 = 320;
/// The size every target is resized to for the second round of checks.
const RESIZED: (u32, u32) = (384, 256);
/// Frames rendered before the images are read, in each round.
const WARM_UP: u32 = 8;

/// A panel facing the camera: width, height, centre, linear colour (unlit).
type Panel = (f32, f32, Vec3, (f32, f32, f32));

/// The scene's panels.
const PANELS: [Panel; 3] = [
    (12.0, 6.0, Vec3::new(0.0, 0.0, -8.0), (0.2, 0.4, 0.8)),
    (1.6, 1.3, Vec3::new(-0.2, -0.15, -3.0), (0.9, 0.3, 0.2)),
    (0.25, 2.4, Vec3::new(-0.225, 0.0, -1.3), (0.8, 0.7, 0.1)),
];
/// What a ray that hits nothing sees (the cameras' clear colour), linear.
const BACKGROUND: [f32; 3] = [0.5, 0.7, 1.0];

/// The cameras: the last two see the scene through distance fog.
const NAMES: [&str; CAMERAS] = ["no-dof", "pinhole", "blurred", "peeled-pinhole", "peeled", "fogged", "peeled-fogged-pinhole"];
const CAMERAS: usize = 7;

/// Each camera's image read back in one round (RGBA16F texels), once it is.
type Round = [Option<Vec<u8>>; CAMERAS];

/// The first round (at `WIDTH` x `HEIGHT`) and the second (at `RESIZED`).
#[derive(Resource, Clone, Default)]
struct Captured(Arc<Mutex<[Round; 2]>>);

#[derive(Resource)]
struct Targets([Handle<Image>; CAMERAS]);

/// A readback's camera and round.
#[derive(Component)]
struct Capture(usize, usize);

fn main() -> AppExit {
    let captured = Captured::default();
    App::new()
        // No window: the app's own loop runs the frames.
        .add_plugins((
            DefaultPlugins.set(WindowPlugin { primary_window: None, exit_condition: ExitCondition::DontExit, ..default() }),
            ScheduleRunnerPlugin::run_loop(Duration::ZERO),
            LensBlurPlugin,
        ))
        .insert_resource(captured.clone())
        .add_systems(Startup, setup)
        .add_systems(Update, (read_back, finish))
        .run();
    check(&captured)
}

fn setup(
    mut commands: Commands,
    mut images: ResMut<Assets<Image>>,
    mut meshes: ResMut<Assets<Mesh>>,
    mut materials: ResMut<Assets<PeelMaterial>>,
) {
    let panel = |meshes: &mut Assets<Mesh>, w: f32, h: f32| meshes.add(Rectangle::new(w, h));
    let unlit = |materials: &mut Assets<PeelMaterial>, r: f32, g: f32, b: f32| {
        materials.add(peel_material(StandardMaterial { base_color: Color::linear_rgb(r, g, b), unlit: true, ..default() }))
    };
    for &(w, h, at, colour) in &PANELS {
        commands.spawn((
            Mesh3d(panel(&mut meshes, w, h)),
            MeshMaterial3d(unlit(&mut materials, colour.0, colour.1, colour.2)),
            Transform::from_translation(at),
        ));
    }
    let targets: [Handle<Image>; CAMERAS] = std::array::from_fn(|_| {
        let mut image = Image::new_target_texture(WIDTH, HEIGHT, TextureFormat::Rgba16Float, None);
        image.texture_descriptor.usage |= TextureUsages::COPY_SRC;
        images.add(image)
    });
    let pinhole = LensBlur { aperture_f_stops: f32::INFINITY, ..default() };
    let blurred = LensBlur { aperture_f_stops: 1.0, sensor_height: 0.036, ..default() };
    let peeled_pinhole = LensBlur { layers: 4, ..pinhole };
    let lenses =
        [None, Some(pinhole), Some(blurred), Some(peeled_pinhole), Some(LensBlur { layers: 4, ..blurred }), None, Some(peeled_pinhole)];
    // The peeled cameras' pass cameras take the orders just below theirs.
    let orders = [0, 1, 2, 10, 20, 30, 40];
    for (i, lens) in lenses.into_iter().enumerate() {
        let mut camera = commands.spawn((
            Camera3d::default(),
            bevy::camera::Hdr,
            bevy::core_pipeline::tonemapping::Tonemapping::None,
            // As the plugin sets on its cameras: the same edges on all three.
            Msaa::Off,
            Camera {
                order: orders[i],
                clear_color: ClearColorConfig::Custom(Color::linear_rgb(BACKGROUND[0], BACKGROUND[1], BACKGROUND[2])),
                ..default()
            },
            RenderTarget::Image(targets[i].clone().into()),
            Transform::from_xyz(0.0, 0.0, 0.0).looking_at(Vec3::new(0.0, 0.0, -3.0), Vec3::Y),
        ));
        if let Some(lens) = lens {
            camera.insert(lens);
        }
        if NAMES[i].contains("fogged") {
            camera.insert(DistanceFog {
                color: Color::linear_rgb(0.6, 0.6, 0.6),
                falloff: FogFalloff::Linear { start: 1.0, end: 12.0 },
                ..default()
            });
        }
    }
    commands.insert_resource(Targets(targets));
}

/// After the warm-up, a readback of each camera's image; once all are back, every target resized
/// (the peeled cameras' passes are made again at the new size), and after another warm-up a
/// second readback.
fn read_back(
    mut commands: Commands,
    targets: Res<Targets>,
    captured: Res<Captured>,
    mut images: ResMut<Assets<Image>>,
    mut frame: Local<u32>,
    mut resized_at: Local<Option<u32>>,
) {
    *frame += 1;
    let round_done = |round: usize| captured.0.lock().is_ok_and(|slots| slots[round].iter().all(Option::is_some));
    let round = match *resized_at {
        None if *frame == WARM_UP => 0,
        None if round_done(0) => {
            for target in &targets.0 {
                if let Some(mut image) = images.get_mut(target) {
                    image.resize(bevy::render::render_resource::Extent3d { width: RESIZED.0, height: RESIZED.1, depth_or_array_layers: 1 });
                }
            }
            *resized_at = Some(*frame);
            return;
        }
        Some(at) if *frame == at + WARM_UP => 1,
        _ => return,
    };
    for (i, target) in targets.0.iter().enumerate() {
        commands.spawn((Readback::texture(target.clone()), Capture(i, round))).observe(store);
    }
}

fn store(event: On<ReadbackComplete>, captures: Query<&Capture>, captured: Res<Captured>, mut commands: Commands) {
    if let Ok(&Capture(camera, round)) = captures.get(event.entity)
        && let Ok(mut slots) = captured.0.lock()
    {
        slots[round][camera].get_or_insert_with(|| event.data.clone());
        commands.entity(event.entity).despawn();
    }
}

fn finish(captured: Res<Captured>, mut exit: MessageWriter<AppExit>, mut frame: Local<u32>) {
    *frame += 1;
    let done = captured.0.lock().is_ok_and(|slots| slots[1].iter().all(Option::is_some));
    if done || *frame > 2 * WARM_UP + 400 {
        exit.write(AppExit::Success);
    }
}

/// The checks of the module docs, on the images of both rounds.
fn check(captured: &Captured) -> AppExit {
    let Ok(slots) = captured.0.lock() else { return AppExit::error() };
    let mut failures = Vec::new();
    for (round, (width, height)) in [(WIDTH, HEIGHT), RESIZED].into_iter().enumerate() {
        println!("== {width}x{height}");
        let Some(bytes) = slots[round].iter().cloned().collect::<Option<Vec<Vec<u8>>>>() else {
            let missing: Vec<&str> = slots[round].iter().zip(NAMES).filter(|(s, _)| s.is_none()).map(|(_, n)| n).collect();
            failures.push(format!("at {width}x{height}, not every camera's image was read back (missing: {})", missing.join(", ")));
            continue;
        };
        check_round(&bytes, round == 0, width, height, &mut failures);
    }
    if failures.is_empty() {
        println!("ok");
        AppExit::Success
    } else {
        eprintln!("FAILED:\n  {}", failures.join("\n  "));
        AppExit::error()
    }
}

/// The checks of one round, at `width` x `height`, into `failures` (prefixed with the size); the
/// first round's images are written out.
fn check_round(bytes: &[Vec<u8>], write: bool, width: u32, height: u32, all_failures: &mut Vec<String>) {
    if let Some(b) = bytes.iter().find(|b| b.len() != (8 * width * height) as usize) {
        all_failures.push(format!("at {width}x{height}: an image of {} bytes read back", b.len()));
        return;
    }
    // RGBA16F texels (rows of 512 or 384 texels, 8 bytes each, need no padding) as linear RGB.
    let images: Vec<Vec<[f32; 3]>> = bytes
        .iter()
        .map(|b| {
            let halves: Vec<u32> = b.chunks(2).map(|h| u16::from_le_bytes([h[0], h[1]]) as u32).collect();
            halves.chunks(4).map(|p| [f16_to_f32(p[0]), f16_to_f32(p[1]), f16_to_f32(p[2])]).collect()
        })
        .collect();
    if write && let Err(e) = write_outputs(&images) {
        all_failures.push(format!("writing out/: {e}"));
    }
    let [none, pinhole, blurred, peeled_pinhole, peeled, fogged, peeled_fogged] = [0, 1, 2, 3, 4, 5, 6].map(|i| &images[i]);
    let mut failures = Vec::new();
    if !images.iter().flatten().flatten().all(|v| v.is_finite()) {
        failures.push("a pixel is not finite".to_string());
    }
    let largest =
        |a: &[[f32; 3]], b: &[[f32; 3]]| a.iter().zip(b).flat_map(|(a, b)| (0..3).map(move |c| (a[c] - b[c]).abs())).fold(0.0f32, f32::max);
    let worst = largest(none, pinhole);
    println!("pinhole through the library against no depth of field: largest difference {worst}");
    if worst != 0.0 {
        failures.push(format!("the pinhole differs from the camera without depth of field by {worst}"));
    }
    // One RGBA16F step of the brightest channel (1.0): 2^-10.
    let worst = largest(none, peeled_pinhole);
    println!("peeled pinhole against no depth of field: largest difference {worst}");
    if worst > 1.0 / 1024.0 {
        failures.push(format!("the peeled pinhole differs from the camera without depth of field by {worst}"));
    }
    // The pass cameras draw the front layers with the camera's fog (and its other view settings).
    let worst = largest(fogged, peeled_fogged);
    println!("peeled pinhole through fog against the fogged camera without depth of field: largest difference {worst}");
    if worst > 1.0 / 1024.0 {
        failures.push(format!("the peeled pinhole through fog differs from the fogged camera by {worst}"));
    }
    if largest(none, fogged) < 0.05 {
        failures.push("the fog changed nothing".to_string());
    }
    let changed = |a: &[f32; 3], b: &[f32; 3]| (0..3).any(|c| (a[c] - b[c]).abs() > 0.01 * b[c].abs().max(0.01));
    let count = |a: &[[f32; 3]], b: &[[f32; 3]]| a.iter().zip(b).filter(|(a, b)| changed(a, b)).count();
    for (name, image) in [("single-layer", blurred), ("peeled", peeled)] {
        let differing = count(pinhole, image);
        println!("pixels the {name} blur changed by more than 1%: {differing} of {}", width * height);
        if differing < (width * height / 50) as usize {
            failures.push(format!("the {name} blur changed only {differing} pixels"));
        }
        // The middle of the pane, in focus at 3 m, away from its edges and the bar's blur.
        let (x, y) = (width / 2 - 40 * width / WIDTH, height / 2 + 20 * height / HEIGHT);
        let at = (y * width + x) as usize;
        if changed(&image[at], &pinhole[at]) {
            failures.push(format!("the pane in focus changed at ({x}, {y}) in the {name} blur: {:?} against {:?}", image[at], pinhole[at]));
        }
    }
    // What the peel adds: the surfaces behind the near bar, seen through its blurred edges.
    let differing = count(blurred, peeled);
    println!("pixels where the peeled blur differs from the single-layer one by more than 1%: {differing}");
    if differing < (width * height / 200) as usize {
        failures.push(format!("the peeled blur differs from the single-layer one in only {differing} pixels"));
    }
    all_failures.extend(failures.into_iter().map(|f| format!("at {width}x{height}: {f}")));
}

/// The three images as EXR, and the scene and camera as glTF for `dof render`.
fn write_outputs(images: &[Vec<[f32; 3]>]) -> Result<(), Box<dyn std::error::Error>> {
    std::fs::create_dir_all("out")?;
    for (name, image) in NAMES.iter().zip(images) {
        exr::prelude::write_rgb_file(format!("out/bevy-{name}.exr"), WIDTH as usize, HEIGHT as usize, |x, y| {
            let p = image[y * WIDTH as usize + x];
            (p[0], p[1], p[2])
        })?;
    }
    // The panels as two triangles each (non-indexed positions), unlit; the camera at the origin
    // looking down -z with Bevy's default projection (45 degrees vertically, near 0.1, far at
    // infinity); the background as the scene's `dof_background`.
    let mut positions: Vec<f32> = Vec::new();
    for &(w, h, at, _) in &PANELS {
        let corner = |sx: f32, sy: f32| [at.x + sx * w / 2.0, at.y + sy * h / 2.0, at.z];
        for c in [corner(-1.0, -1.0), corner(1.0, -1.0), corner(1.0, 1.0), corner(-1.0, -1.0), corner(1.0, 1.0), corner(-1.0, 1.0)] {
            positions.extend(c);
        }
    }
    let bytes: Vec<u8> = positions.iter().flat_map(|v| v.to_le_bytes()).collect();
    std::fs::write("out/bevy-scene.bin", &bytes)?;
    let panel_bytes = 6 * 12;
    let accessors: Vec<String> = (0..PANELS.len())
        .map(|i| {
            let (lo, hi) = bounds(&positions[18 * i..18 * (i + 1)]);
            format!(
                r#"{{"bufferView":0,"byteOffset":{},"componentType":5126,"count":6,"type":"VEC3","min":{lo:?},"max":{hi:?}}}"#,
                i * panel_bytes
            )
        })
        .collect();
    let materials: Vec<String> = PANELS
        .iter()
        .map(|(_, _, _, c)| format!(r#"{{"pbrMetallicRoughness":{{"baseColorFactor":[{},{},{},1]}},"doubleSided":true,"extensions":{{"KHR_materials_unlit":{{}}}}}}"#, c.0, c.1, c.2))
        .collect();
    let meshes: Vec<String> =
        (0..PANELS.len()).map(|i| format!(r#"{{"primitives":[{{"attributes":{{"POSITION":{i}}},"material":{i}}}]}}"#)).collect();
    let nodes: Vec<String> = (0..PANELS.len()).map(|i| format!(r#"{{"mesh":{i}}}"#)).chain([r#"{"camera":0}"#.to_string()]).collect();
    let gltf = format!(
        r#"{{"asset":{{"version":"2.0","generator":"bevy_dof headless example"}},"extensionsUsed":["KHR_materials_unlit"],"scene":0,"scenes":[{{"nodes":[{}],"extras":{{"dof_background":{BACKGROUND:?}}}}}],"nodes":[{}],"meshes":[{}],"materials":[{}],"accessors":[{}],"bufferViews":[{{"buffer":0,"byteLength":{}}}],"buffers":[{{"uri":"bevy-scene.bin","byteLength":{}}}],"cameras":[{{"type":"perspective","perspective":{{"yfov":{},"aspectRatio":{},"znear":0.1}}}}]}}"#,
        (0..=PANELS.len()).map(|i| i.to_string()).collect::<Vec<_>>().join(","),
        nodes.join(","),
        meshes.join(","),
        materials.join(","),
        accessors.join(","),
        bytes.len(),
        bytes.len(),
        std::f32::consts::FRAC_PI_4,
        WIDTH as f32 / HEIGHT as f32,
    );
    std::fs::write("out/bevy-scene.gltf", gltf)?;
    Ok(())
}

/// The smallest and largest of each coordinate of `xyz` (glTF asks them of positions).
fn bounds(xyz: &[f32]) -> ([f32; 3], [f32; 3]) {
    let mut lo = [f32::INFINITY; 3];
    let mut hi = [f32::NEG_INFINITY; 3];
    for p in xyz.chunks(3) {
        for c in 0..3 {
            lo[c] = lo[c].min(p[c]);
            hi[c] = hi[c].max(p[c]);
        }
    }
    (lo, hi)
}
