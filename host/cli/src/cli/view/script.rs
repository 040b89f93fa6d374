//! Scripted changes (`--script`), one applied before each frame: what a user does through the
//! window, for tests that run under Xvfb with nobody at the keyboard.

use super::methods::ViewMethod;
use anyhow::{Result, bail};
use dof::methods::splat::Merge;

#[derive(Clone, Debug, PartialEq)]
pub enum Step {
    Method(ViewMethod),
    Resize(u32, u32),
    Focus(f32),
    FNumber(f32),
    Radius(f32),
    Blades(u32),
    Merge(Merge),
    Tile(u32),
    Rings(u32),
    Orbit(f32),
    Exposure(f32),
    /// Toggle between the tone map and the raw linear values (clamped).
    RawLinear,
    /// A click at window pixel (x, y): focus on what is under it.
    Click(f64, f64),
    Error,
    Close,
}

/// Parses every step first, so that a typo fails before a window opens.
pub fn parse(items: &[String]) -> Result<Vec<Step>> {
    items.iter().map(|s| step(s.trim())).collect()
}

fn step(s: &str) -> Result<Step> {
    let (key, value) = s.split_once('=').unwrap_or((s, ""));
    let number = |v: &str| -> Result<f32> {
        match v.parse::<f32>() {
            Ok(x) if x.is_finite() => Ok(x),
            _ => bail!("--script {s}: expected a finite number"),
        }
    };
    Ok(match key {
        "method" => match ViewMethod::parse(value) {
            Some(m) => Step::Method(m),
            None => bail!("--script {s}: the methods are {}", ViewMethod::names()),
        },
        "resize" => {
            let parsed = value.split_once('x').and_then(|(w, h)| Some((w.parse::<u32>().ok()?, h.parse::<u32>().ok()?)));
            match parsed {
                Some((w, h)) if (16..=super::MAX_EDGE).contains(&w) && (16..=super::MAX_EDGE).contains(&h) => Step::Resize(w, h),
                _ => bail!("--script {s}: expected resize=WxH with edges of 16 to {} pixels", super::MAX_EDGE),
            }
        }
        "focus" => match number(value)? {
            d if d > 0.0 => Step::Focus(d),
            _ => bail!("--script {s}: the focus distance must be positive"),
        },
        "f-number" => match number(value)? {
            n if n > 0.0 => Step::FNumber(n),
            _ => bail!("--script {s}: the f-number must be positive"),
        },
        "radius" => match number(value)? {
            r if r >= 0.0 => Step::Radius(r),
            _ => bail!("--script {s}: the aperture radius must not be negative"),
        },
        "blades" => match value.parse::<u32>() {
            Ok(n) if n == 0 || (3..=64).contains(&n) => Step::Blades(n),
            _ => bail!("--script {s}: blades are 0 (a circle) or 3 to 64"),
        },
        "merge" => match value.parse::<Merge>() {
            Ok(m) => Step::Merge(m),
            Err(_) => bail!("--script {s}: merge is none, 2x2 or 4x4"),
        },
        "tile" => match value.parse::<u32>() {
            Ok(t) if [16, 24, 32].contains(&t) => Step::Tile(t),
            _ => bail!("--script {s}: the tile edge is 16, 24 or 32"),
        },
        "rings" => match value.parse::<u32>() {
            Ok(n) if (1..=dof::methods::ring_gather::MAX_SAMPLE_RINGS).contains(&n) => Step::Rings(n),
            _ => bail!("--script {s}: the ring gather takes 1 to {} rings", dof::methods::ring_gather::MAX_SAMPLE_RINGS),
        },
        "orbit" => Step::Orbit(number(value)?),
        "exposure" => match number(value)? {
            e if e > 0.0 => Step::Exposure(e),
            _ => bail!("--script {s}: the exposure must be positive"),
        },
        "raw-linear" => Step::RawLinear,
        "click" => match value.split_once(':').map(|(x, y)| (number(x), number(y))) {
            Some((Ok(x), Ok(y))) if x >= 0.0 && y >= 0.0 => Step::Click(x as f64, y as f64),
            _ => bail!("--script {s}: expected click=X:Y in window pixels"),
        },
        "error" => Step::Error,
        "close" => Step::Close,
        _ => bail!(
            "--script {s}: unknown step (method=, resize=, focus=, f-number=, radius=, blades=, merge=, tile=, rings=, orbit=, exposure=, raw-linear, click=, error, close)"
        ),
    })
}
