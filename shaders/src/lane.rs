//! Numbers that stand for several pixels at once, so that a per-pixel computation is written once
//! and runs one pixel an invocation on the GPU and several in SIMD registers on the CPU.
//!
//! On the GPU an invocation walks one pixel, and a [`Lanes`] value is a plain `f32` (its mask a
//! `bool`). On the CPU a workgroup's invocations run one after another, so one invocation walks
//! [`Wide::N`] pixels, and a value is a [`Wide`]: eight `f32` whose element-wise operations the
//! compiler turns into vector instructions (no branch inside, so it can). Branches become
//! [`Lanes::select`]: both sides are computed, the mask picks. Every operation is the same IEEE
//! operation on each lane as on the scalar, in the same order, so the pixels' values are the same
//! bits on either target.

use core::ops::{Add, BitAnd, BitOr, Div, Mul, Neg, Not, Sub};

/// A value per pixel.
pub trait Lanes: Copy + Add<Output = Self> + Sub<Output = Self> + Mul<Output = Self> + Div<Output = Self> + Neg<Output = Self> {
    type Mask: LaneMask;
    /// Pixels per value.
    const N: usize;
    fn splat(x: f32) -> Self;
    fn from_fn(f: impl FnMut(usize) -> f32) -> Self;
    fn lane(self, l: usize) -> f32;
    fn sqrt(self) -> Self;
    fn lt(self, o: Self) -> Self::Mask;
    fn le(self, o: Self) -> Self::Mask;
    /// `a` where `m` holds, else `b`.
    fn select(m: Self::Mask, a: Self, b: Self) -> Self;
    /// The largest lane (NaN lanes ignored where another lane is a number).
    fn max_lane(self) -> f32;
}

/// A condition per pixel.
pub trait LaneMask: Copy + BitAnd<Output = Self> + BitOr<Output = Self> + Not<Output = Self> {
    fn splat(b: bool) -> Self;
    fn from_fn(f: impl FnMut(usize) -> bool) -> Self;
    fn test(self, l: usize) -> bool;
    fn any(self) -> bool;
    /// `a` where `self` holds, else `b`.
    #[inline(always)]
    fn pick(self, a: Self, b: Self) -> Self {
        (self & a) | (!self & b)
    }
}

impl Lanes for f32 {
    type Mask = bool;
    const N: usize = 1;
    #[inline(always)]
    fn splat(x: f32) -> f32 {
        x
    }
    #[inline(always)]
    fn from_fn(mut f: impl FnMut(usize) -> f32) -> f32 {
        f(0)
    }
    #[inline(always)]
    fn lane(self, _l: usize) -> f32 {
        self
    }
    #[inline(always)]
    fn sqrt(self) -> f32 {
        crate::math::sqrt(self)
    }
    #[inline(always)]
    fn lt(self, o: f32) -> bool {
        self < o
    }
    #[inline(always)]
    fn le(self, o: f32) -> bool {
        self <= o
    }
    #[inline(always)]
    fn select(m: bool, a: f32, b: f32) -> f32 {
        if m { a } else { b }
    }
    #[inline(always)]
    fn max_lane(self) -> f32 {
        self
    }
}

impl LaneMask for bool {
    #[inline(always)]
    fn splat(b: bool) -> bool {
        b
    }
    #[inline(always)]
    fn from_fn(mut f: impl FnMut(usize) -> bool) -> bool {
        f(0)
    }
    #[inline(always)]
    fn test(self, _l: usize) -> bool {
        self
    }
    #[inline(always)]
    fn any(self) -> bool {
        self
    }
}

#[cfg(not(target_arch = "spirv"))]
pub use wide::{Wide, WideMask};

/// The pixels one invocation works on at once on this target: one on the GPU, [`Wide::N`] on the
/// CPU, where a workgroup's invocations run one after another.
#[cfg(target_arch = "spirv")]
pub type Native = f32;
#[cfg(not(target_arch = "spirv"))]
pub type Native = Wide;

/// Which copy of the passes defined with [`pass_with_simd!`](crate::pass_with_simd) the CPU backend
/// runs.
#[cfg(not(target_arch = "spirv"))]
pub mod isa {
    use core::sync::atomic::{AtomicU8, Ordering::Relaxed};

    /// The instruction sets a pass has a copy for, widest last.
    #[derive(Clone, Copy, Debug, PartialEq, Eq, PartialOrd, Ord)]
    pub enum Isa {
        /// The target's baseline (SSE2 on x86-64).
        Baseline,
        /// AVX2: 16 vector registers of eight lanes.
        Avx2,
        /// AVX-512 (F and VL) on the same eight lanes: 32 vector registers and mask registers.
        Avx512,
    }

    static LIMIT: AtomicU8 = AtomicU8::new(Isa::Avx512 as u8);

    /// The widest copy the passes may run (`Avx512`, the default: the widest the CPU has), for
    /// comparing the copies, which give the same bits. Process-wide.
    pub fn limit(isa: Isa) {
        LIMIT.store(isa as u8, Relaxed)
    }

    /// The copy a pass runs now: the widest the CPU has, within [`limit`].
    #[inline]
    pub fn current() -> Isa {
        let limit = LIMIT.load(Relaxed);
        #[cfg(target_arch = "x86_64")]
        {
            if limit >= Isa::Avx512 as u8 && std::is_x86_feature_detected!("avx512f") && std::is_x86_feature_detected!("avx512vl") {
                return Isa::Avx512;
            }
            if limit >= Isa::Avx2 as u8 && std::is_x86_feature_detected!("avx2") {
                return Isa::Avx2;
            }
        }
        let _ = limit;
        Isa::Baseline
    }
}

/// Defines a kernel pass whose lane arithmetic ([`Wide`]) runs in the widest vector instructions
/// the CPU has: on x86-64 the body is compiled twice more, in functions with the AVX2 and the
/// AVX-512 (F, VL) target features (the closures the body passes to `Group::each` are compiled
/// with them too), and the pass calls the widest copy the CPU has ([`isa`]). The same IEEE
/// operations in every copy (no fused multiply-add), so the same bits. Elsewhere, and on the GPU,
/// the pass is the body.
#[macro_export]
macro_rules! pass_with_simd {
    ($(#[$m:meta])* pub fn $name:ident<$($gp:ident: $gb:path),*>($($arg:ident: $ty:ty),* $(,)?) $body:block) => {
        $(#[$m])*
        pub fn $name<$($gp: $gb),*>($($arg: $ty),*) {
            #[cfg(all(not(target_arch = "spirv"), target_arch = "x86_64"))]
            {
                #[target_feature(enable = "avx2,avx512f,avx512vl")]
                #[allow(clippy::too_many_arguments)]
                unsafe fn avx512<$($gp: $gb),*>($($arg: $ty),*) $body
                #[target_feature(enable = "avx2")]
                #[allow(clippy::too_many_arguments)]
                unsafe fn avx2<$($gp: $gb),*>($($arg: $ty),*) $body
                match $crate::lane::isa::current() {
                    // SAFETY: the CPU has AVX-512 F and VL.
                    $crate::lane::isa::Isa::Avx512 => return unsafe { avx512($($arg),*) },
                    // SAFETY: the CPU has AVX2.
                    $crate::lane::isa::Isa::Avx2 => return unsafe { avx2($($arg),*) },
                    $crate::lane::isa::Isa::Baseline => {}
                }
            }
            $body
        }
    };
}

/// With `portable-simd` (a nightly compiler): `core::simd` vectors and masks.
#[cfg(all(not(target_arch = "spirv"), feature = "portable-simd"))]
mod wide {
    use super::{LaneMask, Lanes};
    use core::ops::{Add, BitAnd, BitOr, Div, Mul, Neg, Not, Sub};
    use core::simd::cmp::SimdPartialOrd;
    use core::simd::num::SimdFloat;
    use core::simd::{Mask, Select, Simd};

    const W: usize = 8;

    /// Eight pixels' values, a portable SIMD vector: each operation is the lanes' IEEE operation,
    /// which the compiler emits as one vector instruction.
    #[derive(Clone, Copy, Debug, PartialEq)]
    pub struct Wide(pub Simd<f32, W>);

    /// Eight pixels' conditions, as SIMD compares give them.
    #[derive(Clone, Copy, Debug, PartialEq)]
    pub struct WideMask(pub Mask<i32, W>);

    macro_rules! lanewise {
        ($ty:ident, $tr:ident, $f:ident, $op:tt) => {
            impl $tr for $ty {
                type Output = $ty;
                #[inline(always)]
                fn $f(self, o: $ty) -> $ty {
                    $ty(self.0 $op o.0)
                }
            }
        };
    }
    lanewise!(Wide, Add, add, +);
    lanewise!(Wide, Sub, sub, -);
    lanewise!(Wide, Mul, mul, *);
    lanewise!(Wide, Div, div, /);
    lanewise!(WideMask, BitAnd, bitand, &);
    lanewise!(WideMask, BitOr, bitor, |);

    impl Neg for Wide {
        type Output = Wide;
        #[inline(always)]
        fn neg(self) -> Wide {
            Wide(-self.0)
        }
    }

    impl Not for WideMask {
        type Output = WideMask;
        #[inline(always)]
        fn not(self) -> WideMask {
            WideMask(!self.0)
        }
    }

    impl Lanes for Wide {
        type Mask = WideMask;
        const N: usize = W;
        #[inline(always)]
        fn splat(x: f32) -> Wide {
            Wide(Simd::splat(x))
        }
        #[inline(always)]
        fn from_fn(f: impl FnMut(usize) -> f32) -> Wide {
            Wide(Simd::from_array(core::array::from_fn(f)))
        }
        #[inline(always)]
        fn lane(self, l: usize) -> f32 {
            self.0[l]
        }
        #[inline(always)]
        fn sqrt(self) -> Wide {
            Wide(std::simd::StdFloat::sqrt(self.0))
        }
        #[inline(always)]
        fn lt(self, o: Wide) -> WideMask {
            WideMask(self.0.simd_lt(o.0))
        }
        #[inline(always)]
        fn le(self, o: Wide) -> WideMask {
            WideMask(self.0.simd_le(o.0))
        }
        #[inline(always)]
        fn select(m: WideMask, a: Wide, b: Wide) -> Wide {
            Wide(m.0.select(a.0, b.0))
        }
        #[inline(always)]
        fn max_lane(self) -> f32 {
            // NaN lanes ignored, as the scalar fold over `v > m` ignores them; −inf for none.
            let v = self.0;
            let v = v.is_nan().select(Simd::splat(f32::NEG_INFINITY), v);
            v.reduce_max()
        }
    }

    impl LaneMask for WideMask {
        #[inline(always)]
        fn splat(b: bool) -> WideMask {
            WideMask(Mask::splat(b))
        }
        #[inline(always)]
        fn from_fn(f: impl FnMut(usize) -> bool) -> WideMask {
            WideMask(Mask::from_array(core::array::from_fn(f)))
        }
        #[inline(always)]
        fn test(self, l: usize) -> bool {
            self.0.test(l)
        }
        #[inline(always)]
        fn any(self) -> bool {
            self.0.any()
        }
    }
}

/// Without `portable-simd` (stable Rust): arrays whose lane loops the compiler vectorises.
#[cfg(all(not(target_arch = "spirv"), not(feature = "portable-simd")))]
mod wide {
    use super::{LaneMask, Lanes};
    use core::ops::{Add, BitAnd, BitOr, Div, Mul, Neg, Not, Sub};

    const W: usize = 8;

    /// Eight pixels' values. Each operation is a loop over the lanes without a branch, which the
    /// compiler emits as vector instructions.
    #[derive(Clone, Copy, Debug, PartialEq)]
    #[repr(C, align(32))]
    pub struct Wide(pub [f32; W]);

    /// Eight pixels' conditions, as SIMD compares give them: all bits set where true.
    #[derive(Clone, Copy, Debug, PartialEq)]
    #[repr(C, align(32))]
    pub struct WideMask(pub [u32; W]);

    macro_rules! lanewise {
        ($ty:ident, $tr:ident, $f:ident, $op:tt) => {
            impl $tr for $ty {
                type Output = $ty;
                #[inline(always)]
                fn $f(self, o: $ty) -> $ty {
                    let mut r = self.0;
                    let mut l = 0;
                    while l < W {
                        r[l] = self.0[l] $op o.0[l];
                        l += 1;
                    }
                    $ty(r)
                }
            }
        };
    }
    lanewise!(Wide, Add, add, +);
    lanewise!(Wide, Sub, sub, -);
    lanewise!(Wide, Mul, mul, *);
    lanewise!(Wide, Div, div, /);
    lanewise!(WideMask, BitAnd, bitand, &);
    lanewise!(WideMask, BitOr, bitor, |);

    impl Neg for Wide {
        type Output = Wide;
        #[inline(always)]
        fn neg(self) -> Wide {
            Wide(self.0.map(|v| -v))
        }
    }

    impl Not for WideMask {
        type Output = WideMask;
        #[inline(always)]
        fn not(self) -> WideMask {
            WideMask(self.0.map(|m| !m))
        }
    }

    #[inline(always)]
    fn mask(b: bool) -> u32 {
        (b as u32).wrapping_neg()
    }

    impl Lanes for Wide {
        type Mask = WideMask;
        const N: usize = W;
        #[inline(always)]
        fn splat(x: f32) -> Wide {
            Wide([x; W])
        }
        #[inline(always)]
        fn from_fn(f: impl FnMut(usize) -> f32) -> Wide {
            Wide(core::array::from_fn(f))
        }
        #[inline(always)]
        fn lane(self, l: usize) -> f32 {
            self.0[l]
        }
        #[inline(always)]
        fn sqrt(self) -> Wide {
            Wide(self.0.map(f32::sqrt))
        }
        #[inline(always)]
        fn lt(self, o: Wide) -> WideMask {
            WideMask(core::array::from_fn(|l| mask(self.0[l] < o.0[l])))
        }
        #[inline(always)]
        fn le(self, o: Wide) -> WideMask {
            WideMask(core::array::from_fn(|l| mask(self.0[l] <= o.0[l])))
        }
        #[inline(always)]
        fn select(m: WideMask, a: Wide, b: Wide) -> Wide {
            Wide(core::array::from_fn(|l| f32::from_bits((m.0[l] & a.0[l].to_bits()) | (!m.0[l] & b.0[l].to_bits()))))
        }
        #[inline(always)]
        fn max_lane(self) -> f32 {
            self.0.iter().fold(f32::NEG_INFINITY, |m, &v| if v > m { v } else { m })
        }
    }

    impl LaneMask for WideMask {
        #[inline(always)]
        fn splat(b: bool) -> WideMask {
            WideMask([mask(b); W])
        }
        #[inline(always)]
        fn from_fn(mut f: impl FnMut(usize) -> bool) -> WideMask {
            WideMask(core::array::from_fn(|l| mask(f(l))))
        }
        #[inline(always)]
        fn test(self, l: usize) -> bool {
            self.0[l] != 0
        }
        #[inline(always)]
        fn any(self) -> bool {
            self.0.iter().fold(0, |a, &m| a | m) != 0
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The same bits, or both NaN (whose sign and payload IEEE leaves open: constant folding and
    /// the CPU's arithmetic differ there).
    fn same(a: f32, b: f32) -> bool {
        a.to_bits() == b.to_bits() || (a.is_nan() && b.is_nan())
    }

    /// Each lane of a wide operation is the scalar operation's bits, NaN and infinities included.
    #[test]
    fn wide_lanes_are_the_scalar_bits() {
        let xs = [0.3f32, -2.5, f32::NAN, f32::INFINITY, 0.0, -0.0, 1e-40, 7.0];
        let ys = [1.1f32, -2.5, 3.0, f32::INFINITY, -0.0, 2.0, 3e38, f32::NAN];
        for base in (0..xs.len()).step_by(Wide::N) {
            let at = |v: &[f32; 8], l: usize| v[(base + l) % v.len()];
            let (a, b) = (Wide::from_fn(|l| at(&xs, l)), Wide::from_fn(|l| at(&ys, l)));
            for l in 0..Wide::N {
                let (x, y) = (at(&xs, l), at(&ys, l));
                assert!(same((a + b).lane(l), x + y));
                assert!(same((a - b).lane(l), x - y));
                assert!(same((a * b).lane(l), x * y));
                assert!(same((a / b).lane(l), x / y));
                assert!(same((-a).lane(l), -x));
                assert!(same(a.sqrt().lane(l), Lanes::sqrt(x)));
                assert_eq!(a.lt(b).test(l), x < y);
                assert_eq!(a.le(b).test(l), x <= y);
                let m = a.lt(b);
                assert!(same(Wide::select(m, a, b).lane(l), f32::select(x < y, x, y)));
                assert_eq!((!m).test(l), !(x < y));
                assert_eq!(m.pick(WideMask::splat(true), WideMask::splat(false)).test(l), x < y);
            }
        }
        assert_eq!(Wide::from_fn(|l| [1.0, 5.0, f32::NAN, -3.0][l % 4]).max_lane(), 5.0);
        assert!(!WideMask::splat(false).any());
        assert!(WideMask::from_fn(|l| l == Wide::N - 1).any());
    }
}
