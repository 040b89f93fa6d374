//! The total order the sort uses on `f32` keys.

/// Maps the bits of an `f32` to a `u32` whose unsigned order is the numeric order of the floats, with
/// two choices made explicit:
/// - `-0.0` and `+0.0` are the same key (they are the same depth);
/// - every NaN maps to `u32::MAX`, after `+inf`: a NaN depth sorts last and never ahead of real data.
///
/// Ties between equal keys are broken by position in the input list, so the sort is stable and its
/// result does not depend on the schedule.
#[inline]
pub fn sort_key(bits: u32) -> u32 {
    let magnitude = bits & 0x7fff_ffff;
    if magnitude > 0x7f80_0000 {
        u32::MAX
    } else if magnitude == 0 {
        0x8000_0000
    } else if bits & 0x8000_0000 != 0 {
        !bits
    } else {
        bits | 0x8000_0000
    }
}
