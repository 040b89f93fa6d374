//! `dof scenes`: the built-in scenes with their lens, multi-layer statistics (with and without the
//! disocclusion buffer) and, on request, how many reference samples they need, and the same scenes
//! exported to glTF: rasterised by depth peeling and rendered by the accumulation buffer, against
//! the exact ray-cast layers and reference.

use super::{MAX_SAMPLES, check_builtin_scenes, check_count, check_no_duplicates};
use anyhow::Context;
use dof::io::write_png_preview;
use dof::layers::RgbImage;
use dof::metrics::compare;
use dof::raster::{AccumulateOptions, accumulate, default_near, peel_layers};
use dof::scene::{
    AutoOptions, BuiltinScene, ExportOptions, LayerOptions, MitsubaExport, MitsubaOptions, ReferenceOptions, SceneLayers, builtin,
    builtin_names, export_glb, export_metadata, export_mitsuba, load_gltf_slice, raycast_layers, reference, reference_auto,
};
use dof_shaders::lens::ThinLens;
use std::path::{Path, PathBuf};
use std::time::Instant;

#[derive(clap::Args)]
pub struct ScenesArgs {
    /// Only these scenes (comma-separated); default all.
    #[arg(long, value_delimiter = ',')]
    only: Vec<String>,
    /// Also compute each scene's automatic reference (raising the sample count until its noise,
    /// full frame and inside the disocclusion buffer, allows measuring methods up to 40 dB within
    /// 0.5 dB) and report the samples it took. Slow: minutes per scene.
    #[arg(long)]
    reference: bool,
    /// Sample cap of the automatic reference.
    #[arg(long, default_value_t = 4096)]
    max_spp: u32,
    /// Write PNGs of the pinhole image, the disocclusion buffer and the reference here.
    #[arg(long)]
    dump: Option<PathBuf>,
    /// Also export each scene to glTF and depth-peel it on `--backend`: the rasterised layers'
    /// statistics next to the exact ones.
    #[arg(long)]
    raster: bool,
    /// With `--raster`: the accumulation buffer at these render counts (comma-separated), each
    /// against the exact reference (`--reference-spp` samples per pixel).
    #[arg(long, value_delimiter = ',')]
    accumulation: Vec<u32>,
    /// Samples per pixel of the exact reference the accumulation buffer is measured against.
    #[arg(long, default_value_t = 1024)]
    reference_spp: u32,
    /// Image size (default: each scene's, 640x360).
    #[arg(long)]
    width: Option<u32>,
    #[arg(long)]
    height: Option<u32>,
    #[arg(long, value_enum, default_value = "cpu")]
    backend: super::render::BackendArg,
    /// Write each scene as binary glTF (`<name>.glb`, with its camera and light) into this folder.
    #[arg(long)]
    export: Option<PathBuf>,
    /// Write each scene that Mitsuba 3 can render exactly (emissive-only surfaces, the reference's
    /// thin lens) as `<name>.xml` into this folder, with `<name>.json` (camera, lens, or why the
    /// scene was skipped) beside it; see `tools/independent_check.py`.
    #[arg(long)]
    export_mitsuba: Option<PathBuf>,
}

/// Largest `--width` and `--height`.
const MAX_EDGE: u32 = 16384;

/// The flags' ranges and names, checked before any work.
fn check_flags(args: &ScenesArgs) -> anyhow::Result<()> {
    check_no_duplicates("--only", &args.only)?;
    check_builtin_scenes("--only", &args.only)?;
    let start = AutoOptions::default().start_spp;
    check_count("--max-spp", "the sample cap of the automatic reference", args.max_spp, start, MAX_SAMPLES)?;
    check_count("--reference-spp", "samples per pixel of the exact reference", args.reference_spp, 1, MAX_SAMPLES)?;
    for &n in &args.accumulation {
        check_count("--accumulation", "renders of the accumulation buffer", n, 1, MAX_SAMPLES)?;
    }
    let counts: Vec<String> = args.accumulation.iter().map(|n| n.to_string()).collect();
    check_no_duplicates("--accumulation", &counts)?;
    if !args.accumulation.is_empty() && !args.raster {
        anyhow::bail!("--accumulation renders the exported glTF scene: it needs --raster");
    }
    for (value, flag) in [(args.width, "--width"), (args.height, "--height")] {
        if let Some(v) = value {
            check_count(flag, "pixels", v, 1, MAX_EDGE)?;
        }
    }
    Ok(())
}

/// A folder a command writes into on request (`--dump`, `--export`, `--export-mitsuba`). It may
/// hold the user's own files: one is never overwritten or removed. What dof wrote there is listed
/// in the folder's manifest, [`MANIFEST`] (one file name a line, added before the file is
/// written), and only those files are replaced or removed by a later run.
struct OutputDir {
    dir: PathBuf,
    flag: &'static str,
    written: Vec<String>,
}

/// The manifest of the files dof wrote into an output folder.
const MANIFEST: &str = ".dof-written";

impl OutputDir {
    /// The folder (made if missing) and its manifest.
    fn open(flag: &'static str, dir: &Path) -> anyhow::Result<OutputDir> {
        if dir.exists() && !dir.is_dir() {
            anyhow::bail!("{flag} {} is not a folder; name a folder for the files", dir.display());
        }
        std::fs::create_dir_all(dir).with_context(|| format!("cannot create the folder {} (for {flag})", dir.display()))?;
        let manifest = dir.join(MANIFEST);
        let written = match std::fs::read_to_string(&manifest) {
            Ok(text) => text.lines().filter(|l| !l.is_empty()).map(str::to_string).collect(),
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => Vec::new(),
            Err(e) => return Err(e).with_context(|| format!("cannot read {} (for {flag})", manifest.display())),
        };
        Ok(OutputDir { dir: dir.to_path_buf(), flag, written })
    }

    /// Refuses a file of this name that dof did not write.
    fn check(&self, name: &str) -> anyhow::Result<()> {
        let path = self.dir.join(name);
        if path.symlink_metadata().is_ok() && !self.written.iter().any(|w| w == name) {
            anyhow::bail!(
                "{} {}: {} already exists and was not written by dof (it is not listed in {}); \
                 dof does not overwrite or remove it: move it away or choose another folder",
                self.flag,
                self.dir.display(),
                path.display(),
                MANIFEST
            );
        }
        Ok(())
    }

    /// The path to write `name` to, recorded in the manifest first.
    fn claim(&mut self, name: &str) -> anyhow::Result<PathBuf> {
        self.check(name)?;
        if !self.written.iter().any(|w| w == name) {
            self.written.push(name.to_string());
            let manifest = self.dir.join(MANIFEST);
            std::fs::write(&manifest, self.written.join("\n") + "\n")
                .with_context(|| format!("cannot write {} (for {})", manifest.display(), self.flag))?;
        }
        Ok(self.dir.join(name))
    }

    /// Removes `name` if dof wrote it (a stale file from an earlier run); a user's file is refused
    /// by [`Self::check`].
    fn remove_stale(&self, name: &str) -> anyhow::Result<()> {
        self.check(name)?;
        let path = self.dir.join(name);
        if path.symlink_metadata().is_ok() {
            std::fs::remove_file(&path).with_context(|| format!("cannot remove the stale {} (for {})", path.display(), self.flag))?;
        }
        Ok(())
    }
}

pub fn run(args: &ScenesArgs) -> anyhow::Result<()> {
    check_flags(args)?;
    let names: Vec<&str> = builtin_names().iter().copied().filter(|n| args.only.is_empty() || args.only.iter().any(|o| o == n)).collect();
    let open = |flag, dir: &Option<PathBuf>| dir.as_deref().map(|d| OutputDir::open(flag, d)).transpose();
    let mut dump = open("--dump", &args.dump)?;
    let mut export = open("--export", &args.export)?;
    let mut mitsuba = open("--export-mitsuba", &args.export_mitsuba)?;
    // Every file the run would write, checked before any work.
    for name in &names {
        if let Some(d) = &dump {
            let mut files = vec![format!("{name}-pinhole.png"), format!("{name}-mask.png")];
            if args.reference {
                files.push(format!("{name}-reference.png"));
            }
            files.iter().try_for_each(|f| d.check(f))?;
        }
        if let Some(d) = &export {
            d.check(&format!("{name}.glb"))?;
        }
        if let Some(d) = &mitsuba {
            d.check(&format!("{name}.xml"))?;
            d.check(&format!("{name}.json"))?;
        }
    }
    for name in names {
        let mut scene = builtin(name)?;
        if args.width.is_some() || args.height.is_some() {
            let (w, h) = (args.width.unwrap_or(scene.camera.width), args.height.unwrap_or(scene.camera.height));
            scene = scene.with_size(w, h);
        }
        let lens = scene.thin_lens()?;
        let start = Instant::now();
        let ml = raycast_layers(&scene.scene, &scene.camera, &lens, &LayerOptions::default())?;
        let (w, wo) = (ml.with_mask, ml.without_mask);
        println!(
            "{name} ({}x{}): {}\n  far-field CoC {:.1} px; guard band {} px; layers (L = 4, umbra threshold): {:.3} fragments/px, {:.1}% multi-layer with the disocclusion buffer ({:.1}% of pixels), {:.3} and {:.1}% without; ray cast in {:.2?}",
            scene.camera.width,
            scene.camera.height,
            scene.description,
            lens.far_limit_px(),
            ml.margin,
            w.fragments_per_pixel(),
            100.0 * w.multi_layer_share(),
            100.0 * ml.mask_share(),
            wo.fragments_per_pixel(),
            100.0 * wo.multi_layer_share(),
            start.elapsed()
        );
        if let Some(dir) = dump.as_mut() {
            let (front, _) = ml.front();
            write_png_preview(dir.claim(&format!("{name}-pinhole.png"))?, &front, 1.0)?;
            let mut mask = RgbImage::new(front.width, front.height);
            let frame = ml.frame_layers();
            for (p, m) in ml.mask.iter().enumerate() {
                let layers = frame.counts[p] as f32;
                mask.data[p] = if *m { [0.25 * layers; 3] } else { [0.0, 0.0, 0.05] };
            }
            write_png_preview(dir.claim(&format!("{name}-mask.png"))?, &mask, 1.0)?;
        }
        if args.reference {
            let start = Instant::now();
            let options = AutoOptions { progress: true, max_spp: args.max_spp, region: Some(ml.mask.clone()), ..Default::default() };
            let r = reference_auto(&scene.scene, &scene.camera, &lens, &options)?;
            let db = |v: Option<f64>| v.map_or("n/a".into(), |v| format!("{v:.2} dB"));
            println!(
                "  reference: {} spp, noise {} full frame, {} inside the buffer (required {}){}, {:.1?}",
                r.spp,
                db(r.noise_psnr_db),
                db(r.region_noise_psnr_db),
                db(r.required_psnr_db),
                if r.capped { ", sample cap reached" } else { "" },
                start.elapsed()
            );
            if let Some(dir) = dump.as_mut() {
                write_png_preview(dir.claim(&format!("{name}-reference.png"))?, &r.image, 1.0)?;
            }
        }
        if args.raster {
            raster(args, &scene, &lens, &ml)?;
        }
        if let Some(dir) = export.as_mut() {
            let bytes = export_glb(&scene.scene, &scene.camera, &ExportOptions::default())?;
            let path = dir.claim(&format!("{name}.glb"))?;
            std::fs::write(&path, bytes).with_context(|| format!("cannot write {} (for --export)", path.display()))?;
            println!("  wrote {}", path.display());
        }
        if let Some(dir) = mitsuba.as_mut() {
            export_mitsuba_files(dir, &scene, &lens)?;
        }
    }
    Ok(())
}

/// `<name>.xml` (when exact) and the `<name>.json` sidecar; a skipped scene says why.
fn export_mitsuba_files(dir: &mut OutputDir, scene: &BuiltinScene, lens: &ThinLens) -> anyhow::Result<()> {
    let name = scene.name;
    let export = export_mitsuba(&scene.scene, &scene.camera, lens, &MitsubaOptions::default())?;
    let xml_name = format!("{name}.xml");
    match &export {
        MitsubaExport::Exact(s) => {
            let xml = dir.claim(&xml_name)?;
            std::fs::write(&xml, &s.xml).with_context(|| format!("cannot write {} (for --export-mitsuba)", xml.display()))?;
            println!("  Mitsuba: wrote {}", xml.display());
            for note in &s.notes {
                println!("    {note}");
            }
        }
        MitsubaExport::Skipped(why) => {
            // A stale file from an earlier export must not be rendered as if it were this one (a
            // file dof did not write is refused before any work instead).
            dir.remove_stale(&xml_name)?;
            println!("  Mitsuba: skipped, not exactly exportable: {why}");
        }
    }
    let text = serde_json::to_string_pretty(&export_metadata(name, &scene.camera, lens, &export))?;
    let json = dir.claim(&format!("{name}.json"))?;
    std::fs::write(&json, text + "\n").with_context(|| format!("cannot write {} (for --export-mitsuba)", json.display()))?;
    Ok(())
}

/// The scene exported to glTF, loaded back, depth-peeled, and (on request) accumulated.
fn raster(args: &ScenesArgs, scene: &BuiltinScene, lens: &ThinLens, exact: &SceneLayers) -> anyhow::Result<()> {
    let glb = export_glb(&scene.scene, &scene.camera, &ExportOptions::default())?;
    let mesh = load_gltf_slice(&glb)?;
    let raster = mesh.raster();
    let mut b = super::render::backend(args.backend)?;
    let near = default_near(lens.focus_distance);
    let start = Instant::now();
    let peeled = peel_layers(b.as_mut(), &raster, &scene.camera, lens, near, &LayerOptions::default())?;
    let (w, wo) = (peeled.image.with_mask, peeled.image.without_mask);
    let (exact_frame, peeled_frame) = (exact.frame_layers(), peeled.image.frame_layers());
    let same = exact_frame.counts.iter().zip(&peeled_frame.counts).filter(|(a, b)| a == b).count();
    println!(
        "  glTF ({} triangles, {:.1} KiB), depth-peeled on {} in {:.2?} ({} passes): {:.3} fragments/px, {:.1}% multi-layer with the buffer, {:.3} and {:.1}% without; {:.2}% of pixels keep as many layers as the exact image",
        mesh.triangles.len(),
        glb.len() as f64 / 1024.0,
        b.device_name(),
        start.elapsed(),
        peeled.passes,
        w.fragments_per_pixel(),
        100.0 * w.multi_layer_share(),
        wo.fragments_per_pixel(),
        100.0 * wo.multi_layer_share(),
        100.0 * same as f64 / exact_frame.counts.len().max(1) as f64
    );
    if args.accumulation.is_empty() {
        return Ok(());
    }
    let start = Instant::now();
    let options = ReferenceOptions { spp: args.reference_spp, progress: true, ..Default::default() };
    let exact_ref = reference(&scene.scene, &scene.camera, lens, &options)?;
    println!("  exact reference: {} spp in {:.1?}", exact_ref.spp, start.elapsed());
    for &n in &args.accumulation {
        let start = Instant::now();
        let acc = accumulate(
            b.as_mut(),
            &raster,
            &scene.camera,
            lens,
            near,
            &AccumulateOptions { samples: n, progress: true, ..Default::default() },
        )?;
        let e = compare(&acc.image, &exact_ref.image, Some(&exact.mask))?;
        println!(
            "  accumulation buffer, {n} renders: PSNR {:.2} dB full frame, {:.2} dB in the disocclusion buffer ({:.1?})",
            e.psnr_db,
            e.psnr_masked_db.unwrap_or(f64::NAN),
            start.elapsed()
        );
    }
    Ok(())
}
