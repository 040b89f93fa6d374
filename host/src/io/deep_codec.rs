//! The lossless codecs OpenEXR allows for deep data (none, RLE, ZIPS and ZIP), undone with bounded
//! output: every stream is decoded to exactly the size its chunk declares, or refused.
//!
//! RLE and ZIP apply the same two byte transforms before compressing: the bytes are split into
//! their even and odd halves, and each byte is stored as the difference to the one before, plus
//! 128. Undoing them follows OpenEXR's file layout documentation.

use ::exr::prelude::Compression;

/// Decodes `packed` to exactly `unpacked_len` bytes. A stream not shorter than its decoded size
/// is stored as it is (OpenEXR stores data that compression would not shrink uncompressed).
pub(super) fn unpack(compression: Compression, packed: &[u8], unpacked_len: usize) -> Result<Vec<u8>, String> {
    if packed.len() == unpacked_len {
        return Ok(packed.to_vec());
    }
    if packed.len() > unpacked_len {
        return Err(format!("{} bytes stored for {unpacked_len} bytes of data", packed.len()));
    }
    let mut bytes = match compression {
        Compression::Uncompressed => return Err(format!("{} bytes stored uncompressed for {unpacked_len} bytes of data", packed.len())),
        Compression::RLE => run_length_decode(packed, unpacked_len)?,
        Compression::ZIP1 | Compression::ZIP16 => miniz_oxide::inflate::decompress_to_vec_zlib_with_limit(packed, unpacked_len)
            .map_err(|e| format!("its zlib stream does not decode ({:?})", e.status))?,
        other => return Err(format!("compression {other:?} is not one OpenEXR allows for deep data")),
    };
    if bytes.len() != unpacked_len {
        return Err(format!("it decodes to {} bytes, not the {unpacked_len} declared", bytes.len()));
    }
    undo_predictor(&mut bytes);
    Ok(interleave(&bytes))
}

/// OpenEXR's run-length code: a signed count byte, then `1 - count` literal bytes when negative,
/// or one byte repeated `count + 1` times.
fn run_length_decode(packed: &[u8], limit: usize) -> Result<Vec<u8>, String> {
    let mut out = Vec::with_capacity(limit);
    let mut i = 0;
    while i < packed.len() {
        let count = packed[i] as i8;
        i += 1;
        if count < 0 {
            let n = (-(count as i32)) as usize;
            let literal = packed.get(i..i + n).ok_or("a run-length literal runs past the end of its chunk")?;
            out.extend_from_slice(literal);
            i += n;
        } else {
            let byte = *packed.get(i).ok_or("a run-length repeat lacks its byte")?;
            out.resize(out.len() + count as usize + 1, byte);
            i += 1;
        }
        if out.len() > limit {
            return Err(format!("its run-length code decodes to more than the {limit} bytes declared"));
        }
    }
    Ok(out)
}

fn undo_predictor(bytes: &mut [u8]) {
    for i in 1..bytes.len() {
        bytes[i] = bytes[i - 1].wrapping_add(bytes[i]).wrapping_sub(128);
    }
}

/// The even bytes come from the first half (its larger part when odd), the odd ones from the second.
fn interleave(split: &[u8]) -> Vec<u8> {
    let half = split.len().div_ceil(2);
    let (even, odd) = split.split_at(half);
    let mut out = Vec::with_capacity(split.len());
    for i in 0..half {
        out.push(even[i]);
        if let Some(&b) = odd.get(i) {
            out.push(b);
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The encoder's two transforms, to check that decoding inverts them.
    fn prepare(data: &[u8]) -> Vec<u8> {
        let mut split: Vec<u8> = data.iter().step_by(2).copied().chain(data.iter().skip(1).step_by(2).copied()).collect();
        for i in (1..split.len()).rev() {
            split[i] = split[i].wrapping_sub(split[i - 1]).wrapping_add(128);
        }
        split
    }

    #[test]
    fn zip_round_trip() {
        let data: Vec<u8> = (0..1001u32).map(|i| (i * 7 % 251) as u8).collect();
        let packed = miniz_oxide::deflate::compress_to_vec_zlib(&prepare(&data), 6);
        assert!(packed.len() < data.len());
        assert_eq!(unpack(Compression::ZIP1, &packed, data.len()).unwrap(), data);
        assert!(unpack(Compression::ZIP1, &packed, data.len() - 1).is_err(), "a declared size that is too small is refused");
        assert!(unpack(Compression::ZIP1, &packed[..packed.len() / 2], data.len()).is_err(), "a truncated stream is refused");
    }

    #[test]
    fn run_length_code() {
        // 3 literal bytes, then 5 copies of 9.
        let packed = [(-3i8) as u8, 1, 2, 3, 4, 9];
        assert_eq!(run_length_decode(&packed, 8).unwrap(), vec![1, 2, 3, 9, 9, 9, 9, 9]);
        assert!(run_length_decode(&packed, 7).is_err());
        assert!(run_length_decode(&[(-3i8) as u8, 1], 8).is_err());
        assert!(run_length_decode(&[4], 8).is_err());
    }

    #[test]
    fn data_that_would_not_shrink_is_stored_as_it_is() {
        assert_eq!(unpack(Compression::ZIP1, &[1, 2, 3], 3).unwrap(), vec![1, 2, 3]);
        assert!(unpack(Compression::Uncompressed, &[1, 2, 3], 4).is_err());
        assert!(unpack(Compression::RLE, &[1, 2, 3, 4], 3).is_err());
    }
}
