//! The plugin in a headless Bevy app, checked: three cameras see the same scene of unlit panels (a
//! far wall, a pane at the focus distance, a near bar) into images of their own. One has no
//! depth of field, one a [`LensBlur`] closed down to a pinhole, one a [`LensBlur`] at f/1.4. After
//! a few frames their images are read back, and the app fails unless:
//! - the pinhole through the library equals the camera without it, within a level of 8 bits
//!   (the library reads and writes the HDR image exactly; only the RGBA16F rounding of its copy
//!   is in between);
//! - the blurred image differs from the pinhole where the near bar and the panels' edges are out
//!   of focus, and equals it in the middle of the pane in focus;
//! - every pixel was written.
//!
//! `cargo run --release --example headless` (from integrations/bevy); it prints the PSNR of the
//! blurred image against the pinhole, and writes the three images as PPM into `out/`.

use bevy::app::ScheduleRunnerPlugin;
use bevy::camera::RenderTarget;
use bevy::prelude::*;
use bevy::render::gpu_readback::{Readback, ReadbackComplete};
use bevy::render::render_resource::{TextureFormat, TextureUsages};
use bevy::window::ExitCondition;
use bevy_dof::{LensBlur, LensBlurPlugin};
use std::sync::{Arc, Mutex};
use std::time::Duration;

const WIDTH: u32 = 512;
const HEIGHT: u32 = 320;
/// Frames rendered before the images are read.
const WARM_UP: u32 = 8;

/// The three cameras, in order.
const NAMES: [&str; 3] = ["no-dof", "pinhole", "blurred"];

#[derive(Resource, Clone, Default)]
struct Captured(Arc<Mutex<[Option<Vec<u8>>; 3]>>);

#[derive(Resource)]
struct Targets([Handle<Image>; 3]);

#[derive(Component)]
struct Capture(usize);

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
    mut materials: ResMut<Assets<StandardMaterial>>,
) {
    let panel = |meshes: &mut Assets<Mesh>, w: f32, h: f32| meshes.add(Rectangle::new(w, h));
    let unlit = |materials: &mut Assets<StandardMaterial>, r: f32, g: f32, b: f32| {
        materials.add(StandardMaterial { base_color: Color::linear_rgb(r, g, b), unlit: true, ..default() })
    };
    for (w, h, at, colour) in [
        (12.0, 6.0, Vec3::new(0.0, 0.0, -8.0), (0.2, 0.4, 0.8)),
        (1.6, 1.3, Vec3::new(-0.2, -0.15, -3.0), (0.9, 0.3, 0.2)),
        (0.25, 2.4, Vec3::new(-0.225, 0.0, -1.3), (0.8, 0.7, 0.1)),
    ] {
        commands.spawn((
            Mesh3d(panel(&mut meshes, w, h)),
            MeshMaterial3d(unlit(&mut materials, colour.0, colour.1, colour.2)),
            Transform::from_translation(at),
        ));
    }
    let targets: [Handle<Image>; 3] = std::array::from_fn(|_| {
        let mut image = Image::new_target_texture(WIDTH, HEIGHT, TextureFormat::Rgba8UnormSrgb, None);
        image.texture_descriptor.usage |= TextureUsages::COPY_SRC;
        images.add(image)
    });
    let lenses = [
        None,
        Some(LensBlur { aperture_f_stops: f32::INFINITY, ..default() }),
        Some(LensBlur { aperture_f_stops: 1.0, sensor_height: 0.036, ..default() }),
    ];
    for (i, lens) in lenses.into_iter().enumerate() {
        let mut camera = commands.spawn((
            Camera3d::default(),
            bevy::camera::Hdr,
            bevy::core_pipeline::tonemapping::Tonemapping::None,
            // As the plugin sets on its cameras: the same edges on all three.
            Msaa::Off,
            Camera { order: i as isize, clear_color: ClearColorConfig::Custom(Color::linear_rgb(0.5, 0.7, 1.0)), ..default() },
            RenderTarget::Image(targets[i].clone().into()),
            Transform::from_xyz(0.0, 0.0, 0.0).looking_at(Vec3::new(0.0, 0.0, -3.0), Vec3::Y),
        ));
        if let Some(lens) = lens {
            camera.insert(lens);
        }
    }
    commands.insert_resource(Targets(targets));
}

/// After the warm-up, a readback of each camera's image.
fn read_back(mut commands: Commands, targets: Res<Targets>, mut frame: Local<u32>) {
    *frame += 1;
    if *frame == WARM_UP {
        for (i, target) in targets.0.iter().enumerate() {
            commands.spawn((Readback::texture(target.clone()), Capture(i))).observe(store);
        }
    }
}

fn store(event: On<ReadbackComplete>, captures: Query<&Capture>, captured: Res<Captured>, mut commands: Commands) {
    if let Ok(capture) = captures.get(event.entity)
        && let Ok(mut slots) = captured.0.lock()
    {
        slots[capture.0].get_or_insert_with(|| event.data.clone());
        commands.entity(event.entity).despawn();
    }
}

fn finish(captured: Res<Captured>, mut exit: MessageWriter<AppExit>, mut frame: Local<u32>) {
    *frame += 1;
    let done = captured.0.lock().is_ok_and(|slots| slots.iter().all(Option::is_some));
    if done || *frame > WARM_UP + 200 {
        exit.write(AppExit::Success);
    }
}

/// The checks of the module docs, on the images read back.
fn check(captured: &Captured) -> AppExit {
    let Ok(slots) = captured.0.lock() else { return AppExit::error() };
    let Some(images) = slots.iter().cloned().collect::<Option<Vec<Vec<u8>>>>() else {
        eprintln!("FAILED: not every camera's image was read back");
        return AppExit::error();
    };
    let _ = std::fs::create_dir_all("out");
    for (name, image) in NAMES.iter().zip(&images) {
        let mut ppm = format!("P6\n{WIDTH} {HEIGHT}\n255\n").into_bytes();
        ppm.extend(image.chunks(4).flat_map(|p| [p[0], p[1], p[2]]));
        let _ = std::fs::write(format!("out/bevy-{name}.ppm"), ppm);
    }
    let (none, pinhole, blurred) = (&images[0], &images[1], &images[2]);
    let mut failures = Vec::new();
    let worst = none.iter().zip(pinhole).map(|(a, b)| a.abs_diff(*b)).max().unwrap_or(0);
    println!("pinhole through the library against no depth of field: largest difference {worst} of 255");
    if worst > 1 {
        failures.push(format!("the pinhole differs from the camera without depth of field by {worst} levels"));
    }
    let mse = pinhole.iter().zip(blurred).map(|(a, b)| (*a as f64 - *b as f64).powi(2)).sum::<f64>() / pinhole.len() as f64;
    let psnr = 10.0 * (255.0f64 * 255.0 / mse.max(1e-12)).log10();
    println!("blurred at f/1.4 against the pinhole: PSNR {psnr:.2} dB");
    let differing =
        pinhole.chunks(4).zip(blurred.chunks(4)).filter(|(a, b)| a.iter().zip(b.iter()).any(|(x, y)| x.abs_diff(*y) > 2)).count();
    println!("pixels the blur changed by more than 2 levels: {differing} of {}", WIDTH * HEIGHT);
    if differing < (WIDTH * HEIGHT / 50) as usize {
        failures.push(format!("the blur changed only {differing} pixels"));
    }
    // The middle of the pane, in focus at 3 m, away from its edges and the bar's blur.
    let at = |x: u32, y: u32| (4 * (y * WIDTH + x)) as usize;
    let (x, y) = (WIDTH / 2 - 40, HEIGHT / 2 + 20);
    let in_focus = (0..3).all(|c| pinhole[at(x, y) + c].abs_diff(blurred[at(x, y) + c]) <= 2);
    if !in_focus {
        failures.push(format!(
            "the pane in focus changed at ({x}, {y}): {:?} against {:?}",
            &blurred[at(x, y)..at(x, y) + 3],
            &pinhole[at(x, y)..at(x, y) + 3]
        ));
    }
    if failures.is_empty() {
        println!("ok");
        AppExit::Success
    } else {
        eprintln!("FAILED:\n  {}", failures.join("\n  "));
        AppExit::error()
    }
}
