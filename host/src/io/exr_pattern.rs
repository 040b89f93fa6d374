//! EXR sequences as compositors name them: `shot-####.exr`, one run of `#` standing for the frame
//! number padded to that many digits (Nuke's and Blender's convention). Numbers wider than the
//! padding are matched too when they have no leading zero (`####` matches `0042` and `12345`).

use std::path::{Path, PathBuf};

use crate::error::{Error, Result};

/// Whether `scene` names an EXR sequence rather than one file.
pub fn is_pattern(scene: &str) -> bool {
    scene.contains('#') && scene.to_ascii_lowercase().ends_with(".exr")
}

/// The pattern's parts: the folder, the file name's text before and after its run of `#`, and the
/// run's length.
struct Pattern<'a> {
    dir: &'a Path,
    prefix: &'a str,
    suffix: &'a str,
    padding: usize,
}

fn parse(pattern: &str) -> Result<Pattern<'_>> {
    let path = Path::new(pattern);
    let name = path.file_name().and_then(|n| n.to_str()).ok_or_else(|| Error::invalid(format!("{pattern} names no file")))?;
    let dir = path.parent().filter(|d| !d.as_os_str().is_empty()).unwrap_or(Path::new("."));
    if dir.to_string_lossy().contains('#') {
        return Err(Error::invalid(format!("the EXR sequence {pattern}: only the file name may hold the frame number's #")));
    }
    let (Some(start), Some(end)) = (name.find('#'), name.rfind('#')) else {
        return Err(Error::invalid(format!("{pattern} holds no # for the frame number")));
    };
    if name[start..=end].chars().any(|c| c != '#') {
        return Err(Error::invalid(format!(
            "the EXR sequence {pattern} holds more than one run of #; write the frame number as one run, such as shot-####.exr"
        )));
    }
    Ok(Pattern { dir, prefix: &name[..start], suffix: &name[end + 1..], padding: end + 1 - start })
}

/// The frame number `name` holds under the pattern, if it matches.
fn frame_number(p: &Pattern, name: &str) -> Option<u64> {
    let digits = name.strip_prefix(p.prefix)?.strip_suffix(p.suffix)?;
    let plain = !digits.is_empty() && digits.bytes().all(|b| b.is_ascii_digit());
    let padded = digits.len() == p.padding || (digits.len() > p.padding && !digits.starts_with('0'));
    if plain && padded { digits.parse().ok() } else { None }
}

/// The files of the sequence in frame order, with their numbers. Refuses a pattern that matches
/// nothing; numbers missing between the first and the last are returned for the caller to report.
pub fn frames(pattern: &str) -> Result<(Vec<(u64, PathBuf)>, Vec<(u64, u64)>)> {
    let p = parse(pattern)?;
    let listing = |e: std::io::Error| Error::invalid(format!("cannot list {} (for the sequence {pattern}): {e}", p.dir.display()));
    let entries = std::fs::read_dir(p.dir).map_err(listing)?;
    let mut found = Vec::new();
    for entry in entries {
        let entry = entry.map_err(listing)?;
        if let Some(n) = entry.file_name().to_str().and_then(|name| frame_number(&p, name)) {
            found.push((n, entry.path()));
        }
    }
    if found.is_empty() {
        return Err(Error::invalid(format!(
            "no file in {} matches the EXR sequence {pattern} ({}, then {} digits, then {})",
            p.dir.display(),
            p.prefix,
            p.padding,
            p.suffix
        )));
    }
    // Numbers are unique: a name's digits are its number's one spelling at this padding.
    found.sort();
    let gaps = found.windows(2).filter(|w| w[1].0 > w[0].0 + 1).map(|w| (w[0].0 + 1, w[1].0 - 1)).collect();
    Ok((found, gaps))
}

/// The `#` spelling of a printf-style frame number (`shot-%04d.exr` → `shot-####.exr`, `%d` →
/// `#`), as Nuke and ffmpeg name sequences; `None` when `scene` holds none.
pub fn from_printf(scene: &str) -> Option<String> {
    let start = scene.find('%')?;
    let rest = &scene[start + 1..];
    let digits = rest.bytes().take_while(u8::is_ascii_digit).count();
    if rest.as_bytes().get(digits) != Some(&b'd') {
        return None;
    }
    let width: usize = if digits == 0 { 1 } else { rest[..digits].parse().ok()? };
    if width == 0 || width > 16 {
        return None;
    }
    Some(format!("{}{}{}", &scene[..start], "#".repeat(width), &rest[digits + 1..]))
}

/// Whether `path` is a file the sequence `pattern` would read as one of its frames (its folder
/// and a name the pattern matches).
pub fn matches(pattern: &str, path: &Path) -> bool {
    let Ok(p) = parse(pattern) else { return false };
    let name = path.file_name().and_then(|n| n.to_str());
    let dir = path.parent().filter(|d| !d.as_os_str().is_empty()).unwrap_or(Path::new("."));
    let same_dir = match (dir.canonicalize(), p.dir.canonicalize()) {
        (Ok(a), Ok(b)) => a == b,
        _ => dir == p.dir,
    };
    same_dir && name.is_some_and(|n| frame_number(&p, n).is_some())
}

/// The name a sequence's outputs take by default: the pattern's file name without its number.
pub fn stem(pattern: &str) -> String {
    let name = Path::new(pattern).file_name().and_then(|n| n.to_str()).unwrap_or("sequence");
    let before = name.split('#').next().unwrap_or("").trim_end_matches(['-', '_', '.', ' ']);
    if before.is_empty() { "sequence".to_string() } else { before.to_string() }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A fresh folder for one test, removed when dropped.
    struct Scratch(PathBuf);
    impl Scratch {
        fn new(name: &str) -> Self {
            let dir = std::env::temp_dir().join(format!("dof-exr-pattern-{}-{name}", std::process::id()));
            let _ = std::fs::remove_dir_all(&dir);
            std::fs::create_dir_all(&dir).unwrap();
            Scratch(dir)
        }
        fn path(&self) -> &Path {
            &self.0
        }
    }
    impl Drop for Scratch {
        fn drop(&mut self) {
            let _ = std::fs::remove_dir_all(&self.0);
        }
    }

    fn touch(dir: &Path, names: &[&str]) {
        for n in names {
            std::fs::write(dir.join(n), b"").unwrap();
        }
    }

    #[test]
    fn matches_padded_numbers_in_order_and_reports_gaps() {
        let dir = Scratch::new("gaps");
        touch(
            dir.path(),
            &["shot-0002.exr", "shot-0001.exr", "shot-0005.exr", "shot-12345.exr", "shot-01.exr", "shot-00001.exr", "other-0003.exr"],
        );
        touch(dir.path(), &["shot-0003.exr.bak", "shot-abcd.exr"]);
        let pattern = dir.path().join("shot-####.exr");
        let (frames, gaps) = frames(pattern.to_str().unwrap()).unwrap();
        let numbers: Vec<u64> = frames.iter().map(|f| f.0).collect();
        assert_eq!(numbers, [1, 2, 5, 12345]);
        assert_eq!(gaps, [(3, 4), (6, 12344)]);
        assert!(frames[0].1.ends_with("shot-0001.exr"));
    }

    #[test]
    fn refuses_what_it_cannot_read_as_a_sequence() {
        let dir = Scratch::new("refuses");
        let none = dir.path().join("shot-####.exr");
        assert!(frames(none.to_str().unwrap()).unwrap_err().to_string().contains("no file"));
        let two_runs = dir.path().join("s##-##.exr");
        assert!(frames(two_runs.to_str().unwrap()).unwrap_err().to_string().contains("more than one run"));
        touch(dir.path(), &["a-7.exr", "a-07.exr"]);
        let one = dir.path().join("a-#.exr");
        // `a-07` has a leading zero beyond the padding of one: not frame 7, so only `a-7` matches.
        assert_eq!(frames(one.to_str().unwrap()).unwrap().0.len(), 1);
    }

    #[test]
    fn printf_frame_numbers_read_as_hashes() {
        assert_eq!(from_printf("in/shot-%04d.exr").as_deref(), Some("in/shot-####.exr"));
        assert_eq!(from_printf("shot.%d.exr").as_deref(), Some("shot.#.exr"));
        assert_eq!(from_printf("shot-####.exr"), None);
        assert_eq!(from_printf("100%.exr"), None);
    }

    #[test]
    fn names_outputs_after_the_pattern() {
        assert_eq!(stem("renders/shot-####.exr"), "shot");
        assert_eq!(stem("####.exr"), "sequence");
        assert!(is_pattern("a/b_###.EXR") && !is_pattern("a.exr") && !is_pattern("x#.gltf"));
    }
}
