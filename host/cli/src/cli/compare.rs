//! `dof compare`: the error of one RGB EXR against another through the project's own metrics
//! ([`dof::metrics::compare`]: PSNR, SSIM and FLIP on the documented display transform), full
//! frame and, given a mask, inside it, e.g. the partial-occlusion region that `dof render` writes
//! as the `mask` plane of its EXR.

use anyhow::{Context, bail};
use dof::io::read_rgb_exr;
use dof::layers::RgbImage;
use dof::metrics::{ImageError, compare};
use serde_json::json;
use std::path::{Path, PathBuf};

#[derive(clap::Args)]
pub struct CompareArgs {
    /// The reference image (an EXR with channels R, G, B).
    reference: PathBuf,
    /// The image measured against it (same size).
    image: PathBuf,
    /// A mask image: its `mask` channel, else its `R` channel; values above 0.5 are inside.
    #[arg(long, conflicts_with = "mask_from")]
    mask: Option<PathBuf>,
    /// The `mask` plane (the partial-occlusion region) of an EXR written by `dof render`.
    #[arg(long)]
    mask_from: Option<PathBuf>,
    /// Print one JSON object instead of text (an infinite PSNR, identical images, is `null`).
    #[arg(long)]
    json: bool,
}

pub fn run(args: &CompareArgs) -> anyhow::Result<()> {
    let reference = read(&args.reference)?;
    let image = read(&args.image)?;
    if (image.width, image.height) != (reference.width, reference.height) {
        bail!(
            "{} is {}x{} but the reference {} is {}x{}: compare images of one size",
            args.image.display(),
            image.width,
            image.height,
            args.reference.display(),
            reference.width,
            reference.height
        );
    }
    let mask = match (&args.mask, &args.mask_from) {
        (Some(path), _) => Some((path, read_plane(path, &["mask", "R"], &reference)?)),
        (None, Some(path)) => Some((path, read_plane(path, &["mask"], &reference)?)),
        (None, None) => None,
    };
    let e = compare(&image, &reference, mask.as_ref().map(|(_, m)| m.as_slice()))?;
    if args.json {
        println!("{}", serde_json::to_string(&as_json(args, &image, mask.as_ref().map(|(p, _)| p.as_path()), &e))?);
    } else {
        println!(
            "{} against {} ({}x{}):\n  full frame: PSNR {} dB, SSIM {:.4}, FLIP {:.4}",
            args.image.display(),
            args.reference.display(),
            image.width,
            image.height,
            db(e.psnr_db),
            e.ssim,
            e.flip
        );
        if let Some((path, _)) = &mask {
            let share = 100.0 * e.masked_pixels as f64 / image.data.len() as f64;
            match (e.psnr_masked_db, e.ssim_masked, e.flip_masked) {
                (Some(p), Some(s), Some(f)) => println!(
                    "  in the mask ({} pixels, {share:.1}%, from {}): PSNR {} dB, SSIM {s:.4}, FLIP {f:.4}",
                    e.masked_pixels,
                    path.display(),
                    db(p)
                ),
                _ => println!("  the mask from {} selects no pixel", path.display()),
            }
        }
    }
    Ok(())
}

fn db(v: f64) -> String {
    if v.is_finite() { format!("{v:.2}") } else { "inf".into() }
}

fn as_json(args: &CompareArgs, image: &RgbImage, mask: Option<&Path>, e: &ImageError) -> serde_json::Value {
    let finite = |v: f64| v.is_finite().then_some(v);
    json!({
        "reference": args.reference.display().to_string(),
        "image": args.image.display().to_string(),
        "width": image.width,
        "height": image.height,
        "psnr_db": finite(e.psnr_db),
        "ssim": e.ssim,
        "flip": e.flip,
        "mask": mask.map(|p| p.display().to_string()),
        "masked_pixels": e.masked_pixels,
        "psnr_masked_db": e.psnr_masked_db.and_then(finite),
        "ssim_masked": e.ssim_masked,
        "flip_masked": e.flip_masked,
    })
}

/// The colour of an EXR; what the NaN/Inf policy repaired is printed as a note.
fn read(path: &Path) -> anyhow::Result<RgbImage> {
    let (image, report) = read_rgb_exr(path)?;
    if report.repaired() > 0 {
        eprintln!("note: {}: {report}", path.display());
    }
    Ok(image)
}

/// The first of the channels `names` found in the EXR at `path` (any layer or part) as a mask
/// (`> 0.5` is inside), checked against the size of `like`.
fn read_plane(path: &Path, names: &[&str], like: &RgbImage) -> anyhow::Result<Vec<bool>> {
    dof::io::check_exr_header(path)?;
    let file =
        exr::prelude::read_all_flat_layers_from_file(path).with_context(|| format!("cannot read the mask EXR {}", path.display()))?;
    let mut found = Vec::new();
    for want in names {
        for layer in &file.layer_data {
            for channel in &layer.channel_data.list {
                let name = channel.name.to_string();
                found.push(name.clone());
                if name != *want {
                    continue;
                }
                let (w, h) = (layer.size.width(), layer.size.height());
                if (w, h) != (like.width as usize, like.height as usize) {
                    bail!("the mask channel `{want}` of {} is {w}x{h}, the images are {}x{}", path.display(), like.width, like.height);
                }
                let inside = |v: f32| v > 0.5;
                return Ok(match &channel.sample_data {
                    exr::prelude::FlatSamples::F32(v) => v.iter().map(|&x| inside(x)).collect(),
                    exr::prelude::FlatSamples::F16(v) => v.iter().map(|x| inside(x.to_f32())).collect(),
                    exr::prelude::FlatSamples::U32(v) => v.iter().map(|&x| x > 0).collect(),
                });
            }
        }
    }
    found.sort();
    found.dedup();
    bail!("{} has no channel {} (it has {})", path.display(), names.join(" or "), found.join(", "))
}
