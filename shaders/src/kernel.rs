//! Declaring a kernel once for both backends.
//!
//! `kernel!` takes a body function (see [`crate::exec`]) and generates
//! - on SPIR-V, the `#[spirv(compute(threads(N)))]` entry point (rust-gpu names it `module::function`), which binds the
//!   storage buffers (descriptor set 0, bindings in the order listed; those marked `read` as `&[u32]`,
//!   which rust-gpu decorates `NonWritable`), the push constants and the workgroup memory, and calls
//!   the body;
//! - on the CPU, a `KernelDesc` constant with the same entry name, workgroup size and binding count,
//!   and a CPU entry that runs the body for one workgroup;
//! - on the CPU, a module named like the entry point holding `Bindings<B>`: one field per storage
//!   buffer, named as the kernel declares it. It implements [`KernelBindings`], which names the
//!   kernel and its push-constant type, so the host dispatches with the bindings by name and typed
//!   parameters (`dof::backend::RunKernel::run`): a missing, extra or misnamed binding, or the
//!   parameters of another kernel, is a compile error.
//!
//! The host refers to kernels only through these constants, so an entry point name is written once.

/// What the host needs to know to run a kernel on either backend.
#[cfg(not(target_arch = "spirv"))]
#[derive(Debug)]
pub struct KernelDesc {
    /// The SPIR-V entry point name.
    pub entry: &'static str,
    /// The entry point of the kernel's variant that scans and reduces in subgroups (declared
    /// `[threads subgroups]`), for devices with subgroup arithmetic: the same results, fewer
    /// barriers. Its module needs the `GroupNonUniform`, `GroupNonUniformArithmetic` and
    /// `GroupNonUniformShuffleRelative` capabilities.
    pub subgroup_entry: Option<&'static str>,
    /// Invocations per workgroup (one-dimensional for every kernel here).
    pub workgroup_size: u32,
    /// Bindings `0..bindings` of descriptor set 0: storage buffers, and the sampled images of
    /// `images`.
    pub bindings: u32,
    /// The bindings the kernel only reads, as a mask (bit `i`: binding `i`): those its declaration
    /// marks `read`, and its sampled images. The buffers are `NonWritable` in its SPIR-V, and its
    /// body can only load them; the CPU backend also faults on a write to one, and the Vulkan
    /// backend's barriers count them as reads, not writes.
    pub read_only: u32,
    /// The bindings that are images, not storage buffers, as a mask: those declared `texture` (a
    /// colour image) or `depth_texture` (a depth image's depth aspect), sampled, and the storage
    /// images of `storage_images`.
    pub images: u32,
    /// Those of `images` declared `depth_texture` (WGSL binds them as `texture_depth_2d`).
    pub depth_images: u32,
    /// Those of `images` the kernel writes, storage images declared `rgba32f_image` or
    /// `rgba16f_image` (the others it samples).
    pub storage_images: u32,
    /// Those of `storage_images` declared `rgba16f_image`.
    pub half_images: u32,
    /// Size of the push constants in bytes.
    pub push_bytes: u32,
    /// Workgroup memory the kernel declares, in bytes (checked against the device limit).
    pub shared_bytes: u32,
    /// Runs one workgroup on the CPU.
    pub cpu: fn(&crate::exec::CpuDispatch),
}

/// A kernel's bindings by name (the `Bindings<B>` that [`kernel!`] generates in the module named
/// like the entry point): which kernel they belong to, its push constants, and the bindings in
/// declaration order (binding `i` of descriptor set 0).
#[cfg(not(target_arch = "spirv"))]
pub trait KernelBindings<B: Copy> {
    /// The kernel these bindings belong to.
    const KERNEL: &'static KernelDesc;
    /// Its push constants.
    type Params: bytemuck::Pod;
    /// The bindings in order, as an array.
    type InOrder: AsRef<[B]>;
    fn in_order(&self) -> Self::InOrder;
}

/// A draw through the graphics pipeline: vertex and fragment entry points reading `bindings`
/// storage buffers (both stages see the push constants), drawn indirectly with `vertices` vertices
/// an instance into an RGBA32F target, adding every fragment (blending) or, with `depth_test`,
/// keeping the nearest. Backends without a graphics pipeline
/// (the CPU backend) run `fallback` instead, a compute kernel over `fallback_tile`-pixel square tiles
/// from the same sources, bound to the draw's buffers, then the indirect command's buffer, then the
/// target (4 words a pixel); before it, `fallback_prepass` (if any) with the same bindings over
/// [`PREPASS_GROUPS`] workgroups (a grid-stride kernel: work the fallback needs and the graphics
/// pipeline does not).
/// Workgroups of a draw's fallback prepass.
#[cfg(not(target_arch = "spirv"))]
pub const PREPASS_GROUPS: u32 = 64;

#[cfg(not(target_arch = "spirv"))]
pub struct DrawDesc {
    pub vertex: &'static str,
    pub fragment: &'static str,
    pub bindings: u32,
    pub push_bytes: u32,
    pub vertices: u32,
    pub fallback: &'static KernelDesc,
    pub fallback_tile: u32,
    pub fallback_prepass: Option<&'static KernelDesc>,
    /// Keep the nearest fragment per pixel (reversed depth test, no blending) instead of adding
    /// every fragment.
    pub depth_test: bool,
}

/// The SPIR-V entry point name rust-gpu gives a function: its path without the crate name.
#[cfg(not(target_arch = "spirv"))]
pub const fn entry_name(path: &'static str) -> &'static str {
    let bytes = path.as_bytes();
    let mut i = 0;
    while i + 1 < bytes.len() {
        if bytes[i] == b':' && bytes[i + 1] == b':' {
            let (_, rest) = bytes.split_at(i + 2);
            return match core::str::from_utf8(rest) {
                Ok(rest) => rest,
                Err(_) => path,
            };
        }
        i += 1;
    }
    path
}

/// The mask of the bindings `which` holds (bit `i`: binding `i`).
#[cfg(not(target_arch = "spirv"))]
pub const fn binding_mask(which: &[bool]) -> u32 {
    let mut mask = 0u32;
    let mut b = 0;
    while b < which.len() {
        if which[b] {
            mask |= 1 << b;
        }
        b += 1;
    }
    mask
}

/// `kernel!(NAME = entry_fn [threads] (Params) shared [u32; N] { read a, read b, c } => body);`
///
/// `[threads subgroups]` also builds the `<entry_fn>::subgroups` entry point
/// (`KernelDesc::subgroup_entry`): the same body, whose group scans and reduces in subgroups
/// ([`crate::wg`]). Mark the kernels that scan or reduce. The entry point is compiled where the
/// crate expanding the macro has the feature `subgroup-kernels` on (this crate's, for its own
/// kernels) and the SPIR-V build enables the subgroup capabilities.
///
/// Each binding is a name, marked `read` when the kernel only reads it. A `read` binding is declared
/// `&[u32]` on the GPU (rust-gpu decorates it `NonWritable`) and reaches the body as a
/// [`Load`](crate::exec::Load) (`GpuRead`), so a store or an atomic to it is a compile error; the
/// others are `&mut [u32]`, a [`Mem`](crate::exec::Mem) (`GpuMem`). On the CPU every binding is a
/// `CpuMem` (both traits), which faults on a write to a `read` binding; `KernelDesc::read_only` is
/// the mask of the `read` bindings.
/// A binding marked `texture` or `depth_texture` is a sampled image (a colour image, or a depth
/// image's depth aspect) and reaches the body as [`Texels`](crate::texels::Texels): fetched on the
/// GPU, decoded from the CPU backend's packed image on the CPU (`KernelDesc::images`). One marked
/// `rgba32f_image` or `rgba16f_image` is a storage image the kernel writes, a
/// [`TexelsMut`](crate::texels::TexelsMut) (`KernelDesc::storage_images`).
/// The body is called as `body(&mut group, &params, &mut shared, bindings...)`; without `shared`, as
/// `body(&mut group, &params, bindings...)`, the bindings in declaration order.
#[macro_export]
macro_rules! kernel {
    ($(#[$doc:meta])* $desc:ident = $entry:ident [$threads:tt $($sg:ident)?] ($params:ty) shared [u32; $n:expr] { $($bind:tt)* }
        => $body:ident) => {
        $crate::kernel!(@parse [$(#[$doc])* $desc $entry [$threads] [$($sg)?] ($params) $body
            [#[spirv(workgroup)] shared: &mut [u32; $n],] [shared,] [&mut [0u32; $n],] ($n)] [] $($bind)*);
    };
    ($(#[$doc:meta])* $desc:ident = $entry:ident [$threads:tt $($sg:ident)?] ($params:ty) { $($bind:tt)* } => $body:ident) => {
        $crate::kernel!(@parse [$(#[$doc])* $desc $entry [$threads] [$($sg)?] ($params) $body [] [] [] (0)] [] $($bind)*);
    };

    // Reads the binding list into `[mode name]` pairs (`read`, `write`, `texture`, `depth_texture`).
    (@parse [$($decl:tt)*] [$($acc:tt)*] read $b:ident $(, $($rest:tt)*)?) => {
        $crate::kernel!(@parse [$($decl)*] [$($acc)* [read $b]] $($($rest)*)?);
    };
    (@parse [$($decl:tt)*] [$($acc:tt)*] texture $b:ident $(, $($rest:tt)*)?) => {
        $crate::kernel!(@parse [$($decl)*] [$($acc)* [texture $b]] $($($rest)*)?);
    };
    (@parse [$($decl:tt)*] [$($acc:tt)*] depth_texture $b:ident $(, $($rest:tt)*)?) => {
        $crate::kernel!(@parse [$($decl)*] [$($acc)* [depth_texture $b]] $($($rest)*)?);
    };
    (@parse [$($decl:tt)*] [$($acc:tt)*] rgba32f_image $b:ident $(, $($rest:tt)*)?) => {
        $crate::kernel!(@parse [$($decl)*] [$($acc)* [rgba32f_image $b]] $($($rest)*)?);
    };
    (@parse [$($decl:tt)*] [$($acc:tt)*] rgba16f_image $b:ident $(, $($rest:tt)*)?) => {
        $crate::kernel!(@parse [$($decl)*] [$($acc)* [rgba16f_image $b]] $($($rest)*)?);
    };
    (@parse [$($decl:tt)*] [$($acc:tt)*] $b:ident $(, $($rest:tt)*)?) => {
        $crate::kernel!(@parse [$($decl)*] [$($acc)* [write $b]] $($($rest)*)?);
    };
    (@parse [$(#[$doc:meta])* $desc:ident $entry:ident [$threads:tt] [$($sg:ident)?] ($params:ty) $body:ident [$($sh:tt)*] [$($sh_arg:tt)*]
        [$($cpu_sh:tt)*] ($n:expr)] [$([$mode:ident $buf:ident])*]) => {
        $crate::kernel!(@gpu [$threads $($sg)?] $entry ($params) $body [$($sh)*] [$($sh_arg)*] [] [] [0 1 2 3 4 5 6 7 8 9 10 11]
            $([$mode $buf])*);
        $crate::kernel!(@cpu $(#[$doc])* $desc $entry [$threads] [$($sg)?] ($params) ($n) $body [$($cpu_sh)*] $([$mode $buf])*);
    };

    // Accumulates one entry-point parameter per binding, numbered in order (`#[spirv(storage_buffer)]`
    // `&[u32]` for a `read` binding, `&mut [u32]` for a written one, a sampled image for a texture),
    // and the argument the body gets for it.
    (@gpu [$threads:tt $($sg:ident)?] $entry:ident ($params:ty) $body:ident [$($sh:tt)*] [$($sh_arg:tt)*] [$($acc:tt)*] [$($arg:tt)*]
        [$n:tt $($ns:tt)*] [read $b:ident] $($rest:tt)*) => {
        $crate::kernel!(@gpu [$threads $($sg)?] $entry ($params) $body [$($sh)*] [$($sh_arg)*]
            [$($acc)* #[spirv(descriptor_set = 0, binding = $n, storage_buffer)] $b: &[u32],]
            [$($arg)* $crate::exec::GpuRead($b),]
            [$($ns)*] $($rest)*);
    };
    (@gpu [$threads:tt $($sg:ident)?] $entry:ident ($params:ty) $body:ident [$($sh:tt)*] [$($sh_arg:tt)*] [$($acc:tt)*] [$($arg:tt)*]
        [$n:tt $($ns:tt)*] [write $b:ident] $($rest:tt)*) => {
        $crate::kernel!(@gpu [$threads $($sg)?] $entry ($params) $body [$($sh)*] [$($sh_arg)*]
            [$($acc)* #[spirv(descriptor_set = 0, binding = $n, storage_buffer)] $b: &mut [u32],]
            [$($arg)* $crate::exec::GpuMem($b),]
            [$($ns)*] $($rest)*);
    };
    (@gpu [$threads:tt $($sg:ident)?] $entry:ident ($params:ty) $body:ident [$($sh:tt)*] [$($sh_arg:tt)*] [$($acc:tt)*] [$($arg:tt)*]
        [$n:tt $($ns:tt)*] [texture $b:ident] $($rest:tt)*) => {
        $crate::kernel!(@gpu [$threads $($sg)?] $entry ($params) $body [$($sh)*] [$($sh_arg)*]
            [$($acc)* #[spirv(descriptor_set = 0, binding = $n)] $b: &$crate::texels::ColorImage,]
            [$($arg)* $b,]
            [$($ns)*] $($rest)*);
    };
    (@gpu [$threads:tt $($sg:ident)?] $entry:ident ($params:ty) $body:ident [$($sh:tt)*] [$($sh_arg:tt)*] [$($acc:tt)*] [$($arg:tt)*]
        [$n:tt $($ns:tt)*] [depth_texture $b:ident] $($rest:tt)*) => {
        $crate::kernel!(@gpu [$threads $($sg)?] $entry ($params) $body [$($sh)*] [$($sh_arg)*]
            [$($acc)* #[spirv(descriptor_set = 0, binding = $n)] $b: &$crate::texels::DepthImage,]
            [$($arg)* $b,]
            [$($ns)*] $($rest)*);
    };
    (@gpu [$threads:tt $($sg:ident)?] $entry:ident ($params:ty) $body:ident [$($sh:tt)*] [$($sh_arg:tt)*] [$($acc:tt)*] [$($arg:tt)*]
        [$n:tt $($ns:tt)*] [rgba32f_image $b:ident] $($rest:tt)*) => {
        $crate::kernel!(@gpu [$threads $($sg)?] $entry ($params) $body [$($sh)*] [$($sh_arg)*]
            [$($acc)* #[spirv(descriptor_set = 0, binding = $n)] $b: &$crate::texels::Rgba32fImage,]
            [$($arg)* $b,]
            [$($ns)*] $($rest)*);
    };
    (@gpu [$threads:tt $($sg:ident)?] $entry:ident ($params:ty) $body:ident [$($sh:tt)*] [$($sh_arg:tt)*] [$($acc:tt)*] [$($arg:tt)*]
        [$n:tt $($ns:tt)*] [rgba16f_image $b:ident] $($rest:tt)*) => {
        $crate::kernel!(@gpu [$threads $($sg)?] $entry ($params) $body [$($sh)*] [$($sh_arg)*]
            [$($acc)* #[spirv(descriptor_set = 0, binding = $n)] $b: &$crate::texels::Rgba16fImage,]
            [$($arg)* $b,]
            [$($ns)*] $($rest)*);
    };
    (@gpu [$threads:tt $($sg:ident)?] $entry:ident ($params:ty) $body:ident [$($sh:tt)*] [$($sh_arg:tt)*] [$($acc:tt)*] [$($arg:tt)*]
        [$($ns:tt)*]) => {
        #[cfg(target_arch = "spirv")]
        #[spirv_std::spirv(compute(threads($threads)))]
        #[allow(clippy::too_many_arguments)]
        pub fn $entry(
            #[spirv(local_invocation_index)] local_index: u32,
            #[spirv(workgroup_id)] workgroup_id: spirv_std::glam::UVec3,
            #[spirv(num_workgroups)] num_workgroups: spirv_std::glam::UVec3,
            #[spirv(push_constant)] params: &$params,
            $($sh)*
            $($acc)*
        ) {
            let mut group = $crate::exec::GpuGroup {
                size: $threads,
                local_index,
                workgroup_id: workgroup_id.to_array(),
                num_workgroups: num_workgroups.to_array(),
            };
            $body(&mut group, params, $($sh_arg)* $($arg)*)
        }
        $crate::kernel!(@gpu_subgroups [$($sg)?] [$threads] $entry ($params) $body [$($sh)*] [$($sh_arg)*] [$($acc)*] [$($arg)*]);
    };

    // A kernel marked `subgroups` has a second entry point, `<entry>::subgroups`, whose group runs
    // the workgroup scans and reductions in subgroups.
    (@gpu_subgroups [] $($rest:tt)*) => {};
    (@gpu_subgroups [subgroups] [$threads:tt] $entry:ident ($params:ty) $body:ident [$($sh:tt)*] [$($sh_arg:tt)*] [$($acc:tt)*]
        [$($arg:tt)*]) => {
        #[cfg(all(target_arch = "spirv", feature = "subgroup-kernels"))]
        pub mod $entry {
            #[allow(unused_imports)]
            use super::*;
            #[spirv_std::spirv(compute(threads($threads)))]
            #[allow(clippy::too_many_arguments)]
            pub fn subgroups(
                #[spirv(local_invocation_index)] local_index: u32,
                #[spirv(workgroup_id)] workgroup_id: spirv_std::glam::UVec3,
                #[spirv(num_workgroups)] num_workgroups: spirv_std::glam::UVec3,
                #[spirv(subgroup_size)] subgroup_size: u32,
                #[spirv(num_subgroups)] num_subgroups: u32,
                #[spirv(subgroup_id)] subgroup_id: u32,
                #[spirv(subgroup_local_invocation_id)] lane: u32,
                #[spirv(push_constant)] params: &$params,
                $($sh)*
                $($acc)*
            ) {
                let mut group = $crate::exec::GpuSubgroupGroup {
                    group: $crate::exec::GpuGroup {
                        size: $threads,
                        local_index,
                        workgroup_id: workgroup_id.to_array(),
                        num_workgroups: num_workgroups.to_array(),
                    },
                    subgroup_size,
                    num_subgroups,
                    subgroup_id,
                    lane,
                };
                $body(&mut group, params, $($sh_arg)* $($arg)*)
            }
        }
    };
    (@subgroup_entry [] $entry:ident) => { None };
    (@subgroup_entry [subgroups] $entry:ident) => {
        Some($crate::kernel::entry_name(concat!(module_path!(), "::", stringify!($entry), "::subgroups")))
    };

    (@is_read read) => { true };
    (@is_read texture) => { true };
    (@is_read depth_texture) => { true };
    (@is_read $mode:ident) => { false };
    (@is_image texture) => { true };
    (@is_image depth_texture) => { true };
    (@is_image rgba32f_image) => { true };
    (@is_image rgba16f_image) => { true };
    (@is_image $mode:ident) => { false };
    (@is_depth depth_texture) => { true };
    (@is_depth $mode:ident) => { false };
    (@is_storage rgba32f_image) => { true };
    (@is_storage rgba16f_image) => { true };
    (@is_storage $mode:ident) => { false };
    (@is_half rgba16f_image) => { true };
    (@is_half $mode:ident) => { false };
    (@cpu_bind texture $d:ident $b:ident) => { $d.texels($b) };
    (@cpu_bind depth_texture $d:ident $b:ident) => { $d.texels($b) };
    (@cpu_bind rgba32f_image $d:ident $b:ident) => { $d.texels_mut($b) };
    (@cpu_bind rgba16f_image $d:ident $b:ident) => { $d.texels_mut($b) };
    (@cpu_bind $mode:ident $d:ident $b:ident) => { $d.mem($b) };

    (@cpu $(#[$doc:meta])* $desc:ident $entry:ident [$threads:tt] [$($sg:ident)?] ($params:ty) ($n:expr) $body:ident
        [$($sh_arg:tt)*] $([$mode:ident $buf:ident])*) => {
        /// The bindings of the kernel of this name, by name (see [`kernel!`](crate::kernel!)).
        #[cfg(not(target_arch = "spirv"))]
        pub mod $entry {
            #[allow(unused_imports)]
            use super::*;
            /// One binding per field (a storage buffer or a sampled image), named as the kernel
            /// declares it.
            #[derive(Clone, Copy, Debug, PartialEq)]
            pub struct Bindings<B> {
                $(pub $buf: B,)*
            }
            impl<B: Copy> $crate::kernel::KernelBindings<B> for Bindings<B> {
                const KERNEL: &'static $crate::kernel::KernelDesc = &super::$desc;
                type Params = $params;
                type InOrder = [B; [$(stringify!($buf)),*].len()];
                fn in_order(&self) -> Self::InOrder {
                    [$(self.$buf),*]
                }
            }
        }
        $(#[$doc])*
        #[cfg(not(target_arch = "spirv"))]
        pub const $desc: $crate::kernel::KernelDesc = {
            fn cpu(d: &$crate::exec::CpuDispatch) {
                let params: $params = $crate::exec::params(d.push);
                let mut _binding = 0usize;
                $(let $buf = $crate::kernel!(@cpu_bind $mode d _binding); _binding += 1;)*
                let mut group = d.group($threads);
                $body(&mut group, &params, $($sh_arg)* $($buf),*);
                d.count_barriers(&group);
            }
            $crate::kernel::KernelDesc {
                entry: $crate::kernel::entry_name(concat!(module_path!(), "::", stringify!($entry))),
                subgroup_entry: $crate::kernel!(@subgroup_entry [$($sg)?] $entry),
                workgroup_size: $threads,
                bindings: [$(stringify!($buf)),*].len() as u32,
                read_only: $crate::kernel::binding_mask(&[$($crate::kernel!(@is_read $mode)),*]),
                images: $crate::kernel::binding_mask(&[$($crate::kernel!(@is_image $mode)),*]),
                depth_images: $crate::kernel::binding_mask(&[$($crate::kernel!(@is_depth $mode)),*]),
                storage_images: $crate::kernel::binding_mask(&[$($crate::kernel!(@is_storage $mode)),*]),
                half_images: $crate::kernel::binding_mask(&[$($crate::kernel!(@is_half $mode)),*]),
                push_bytes: core::mem::size_of::<$params>() as u32,
                shared_bytes: 4 * ($n) as u32,
                cpu,
            }
        };
    };
}
