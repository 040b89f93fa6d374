//! Pass 2: each tile's near-field radius dilated over the tiles it reaches, and its highlight reach.

use super::*;

/// One invocation a tile: the near-field radius dilated over the tiles that radius reaches
/// (measured from the nearest edges of the two tiles), itself included, and how far to look for
/// highlights whose disc reaches it. A neighbour's radius fades in over the last tile of its reach
/// instead of switching on, so the dilated radius (the near kernel's size) moves continuously.
pub fn dilate_pass<G: Group, R: Load, M: Mem>(g: &mut G, p: &RingGatherParams, tiles: R, bright: R, mut dilated: M) {
    let (tw, th) = (p.tiles_x(), p.tiles_y());
    let reach = p.dilation_tiles() as i32;
    crate::wg::for_each_item(g, tw * th, |t| {
        let (tx, ty) = ((t % tw) as i32, (t / tw) as i32);
        let mut widest = 0.0f32;
        let mut look = 0u32;
        let mut dy = -reach;
        while dy <= reach {
            let ny = ty + dy;
            let mut dx = -reach;
            while ny >= 0 && ny < th as i32 && dx <= reach {
                let nx = tx + dx;
                if nx >= 0 && nx < tw as i32 {
                    let n = ny as u32 * tw + nx as u32;
                    let gx = (maxf(absf(dx as f32) - 1.0, 0.0)) * TILE as f32;
                    let gy = (maxf(absf(dy as f32) - 1.0, 0.0)) * TILE as f32;
                    let gap = crate::math::sqrt(gx * gx + gy * gy);
                    let r = f32::from_bits(tiles.load(n));
                    widest = maxf(widest, r * saturate((r - gap) / TILE as f32 + 1.0));
                    // Highlights: radii in pixels of the frame, gaps in half-resolution pixels.
                    let record = BRIGHT_TILE_WORDS * n;
                    if bright.load(record) > 0 && f32::from_bits(bright.load(record + 1)) + 1.0 >= 2.0 * gap {
                        let side = maxf(absf(dx as f32), absf(dy as f32)) as u32 + 1;
                        look = if side > look { side } else { look };
                    }
                }
                dx += 1;
            }
            dy += 1;
        }
        dilated.store(DILATED_WORDS * t, widest.to_bits());
        dilated.store(DILATED_WORDS * t + 1, look);
    });
}
