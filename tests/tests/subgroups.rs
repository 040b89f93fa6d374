//! The kernels' subgroup variants (`KernelDesc::subgroup_entry`) against the same kernels without
//! subgroups: they change only how a workgroup scans and reduces words (integer operations, in
//! another order), so every method's image is the same bits with and without them, on each
//! backend, and at every subgroup width the CPU emulates.

use dof::backend::{Backend, CpuBackend, Subgroups, VulkanOptions, WgpuOptions};
use dof::frame::{METHODS, MethodOptions};
use dof::methods::one_shot::one_shot;
use dof::stress::{noise_with_sky, test_lens};
use dof_tests::{vulkan_with, wgpu_with};

/// Every registered method's image on `backend`, as bits.
fn images(backend: &mut dyn Backend) -> Vec<(&'static str, Vec<u32>)> {
    let image = noise_with_sky(48, 32, 3);
    let lens = test_lens(0.02);
    METHODS
        .iter()
        .map(|m| {
            let out = one_shot(backend, m, &MethodOptions::default(), &image, &lens).unwrap_or_else(|e| panic!("{}: {e}", m.name));
            (m.name, out.image.data.as_flattened().iter().map(|v| v.to_bits()).collect())
        })
        .collect()
}

fn assert_same(a: &[(&str, Vec<u32>)], b: &[(&str, Vec<u32>)], what: &str) {
    for ((name, x), (_, y)) in a.iter().zip(b) {
        let differ = x.iter().zip(y).filter(|(p, q)| p != q).count();
        assert_eq!(differ, 0, "{name}: {differ} of {} values differ {what}", x.len());
    }
}

#[test]
fn the_cpu_gives_the_same_bits_at_every_subgroup_width() {
    let mut cpu = CpuBackend::new();
    assert!(cpu.limits().subgroup_kernels, "the CPU backend runs the subgroup variants by default");
    let default = images(&mut cpu);
    for width in [None, Some(4), Some(8), Some(32), Some(64)] {
        cpu.set_subgroup_size(width).unwrap();
        assert_eq!(cpu.limits().subgroup_kernels, width.is_some());
        assert_same(&default, &images(&mut cpu), &format!("in subgroups of {width:?} and of the workgroup"));
    }
    for bad in [0, 1, 3, 48, 512] {
        let e = cpu.set_subgroup_size(Some(bad)).unwrap_err().to_string();
        assert!(e.contains("powers of two"), "{bad}: {e}");
    }
}

#[test]
fn vulkan_gives_the_same_bits_with_and_without_subgroups() {
    let Some(mut with) = vulkan_with(VulkanOptions { validation: true, subgroups: Subgroups::Required, ..Default::default() }) else {
        return;
    };
    assert!(with.limits().subgroup_kernels);
    let on = images(&mut with);
    assert!(with.take_diagnostics().is_empty(), "validation: {:?}", with.take_diagnostics());
    drop(with);
    let Some(mut without) = vulkan_with(VulkanOptions { validation: true, subgroups: Subgroups::Off, ..Default::default() }) else {
        return;
    };
    assert!(!without.limits().subgroup_kernels);
    assert_same(&on, &images(&mut without), "with subgroups and without, on Vulkan");
    assert!(without.take_diagnostics().is_empty());
}

#[test]
fn wgpu_gives_the_same_bits_with_and_without_subgroups() {
    let options = |subgroups| WgpuOptions { backends: wgpu::Backends::VULKAN, subgroups, ..Default::default() };
    let Some(mut with) = wgpu_with(options(Subgroups::Required)) else { return };
    assert!(with.limits().subgroup_kernels && with.device().features().contains(wgpu::Features::SUBGROUP));
    let on = images(&mut with);
    assert!(with.take_diagnostics().is_empty());
    let Some(mut without) = wgpu_with(options(Subgroups::Off)) else { return };
    assert!(!without.limits().subgroup_kernels);
    assert_same(&on, &images(&mut without), "with subgroups and without, on wgpu");
    // Turned off on the device that has them: the pipelines are made again, without.
    with.set_subgroups(Subgroups::Off).unwrap();
    assert!(!with.limits().subgroup_kernels);
    assert_same(&on, &images(&mut with), "after set_subgroups(Off)");
}
