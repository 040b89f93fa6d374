//! Progress bars on stderr for long renders: `indicatif` with the `progress` feature; without it
//! nothing is shown and the `progress` options are ignored.

/// A progress bar on stderr (feature `progress`).
pub(crate) struct Progress {
    #[cfg(feature = "progress")]
    bar: indicatif::ProgressBar,
}

impl Progress {
    /// A bar of `len` steps drawn with `template` (`indicatif`'s syntax) showing `message`; `None`
    /// unless `show` and the `progress` feature is on.
    pub(crate) fn new(show: bool, len: u64, template: &str, message: &str) -> Option<Progress> {
        #[cfg(feature = "progress")]
        if show {
            let bar = indicatif::ProgressBar::new(len);
            if let Ok(style) = indicatif::ProgressStyle::with_template(template) {
                bar.set_style(style);
            }
            bar.set_message(message.to_string());
            return Some(Progress { bar });
        }
        let _ = (show, len, template, message);
        None
    }

    pub(crate) fn inc(&self, steps: u64) {
        #[cfg(feature = "progress")]
        self.bar.inc(steps);
        let _ = steps;
    }

    pub(crate) fn set_position(&self, position: u64) {
        #[cfg(feature = "progress")]
        self.bar.set_position(position);
        let _ = position;
    }

    pub(crate) fn finish_and_clear(&self) {
        #[cfg(feature = "progress")]
        self.bar.finish_and_clear();
    }
}
