//! Every stiff and extreme case of `dof::stress` as a test: each method of the registry on the CPU
//! backend and on Vulkan (lavapipe in CI, validation on) meets the case's stated expectation.

use dof::backend::{Backend, CpuBackend};
use dof::eval::methods::evaluated_methods;
use dof::stress::{Outcome, case};
use dof_tests::{assert_clean, vulkan};

fn check(name: &str) {
    let case = case(name).unwrap();
    let mut vk = vulkan();
    for method in evaluated_methods() {
        let mut backends: Vec<&mut dyn Backend> = Vec::new();
        let mut cpu = CpuBackend::new();
        backends.push(&mut cpu);
        if let (Some(vk), true) = (vk.as_mut(), method.uses_backend()) {
            backends.push(vk);
        }
        for backend in backends {
            let kind = backend.kind();
            if let Outcome::Fail(why) = case.run(method.as_ref(), backend) {
                panic!("{name} on {} ({kind}): {why} (expected: {})", method.name(), case.expectation);
            }
        }
    }
    if let Some(vk) = vk.as_mut() {
        assert_clean(vk);
    }
}

macro_rules! cases {
    ($($test:ident => $name:literal),* $(,)?) => {
        $(#[test] fn $test() { check($name); })*

        /// The list above names every case.
        #[test]
        fn every_case_is_a_test() {
            let listed = [$($name),*];
            for c in dof::stress::cases() {
                assert!(listed.contains(&c.name), "stress case {} has no test", c.name);
            }
        }
    };
}

cases! {
    pinhole => "pinhole",
    sub_pixel_coc => "sub-pixel-coc",
    flat_field => "flat-field",
    nan_inf_input => "nan-inf-input",
    hdr_beyond_half => "hdr-beyond-half",
    colour_at_f32_max => "colour-at-f32-max",
    colour_1e38 => "colour-1e38",
    spots_1e12_every_97 => "spots-1e12-every-97",
    spot_1e11_in_dim => "spot-1e11-in-dim",
    spots_1e12_over_dim => "spots-1e12-over-dim",
    subnormal_colours => "subnormal-colours",
    background_at_limit => "background-at-limit",
    focus_at_focal_length => "focus-at-focal-length",
    coc_beyond_rings => "coc-beyond-rings",
    sky_at_infinity => "sky-at-infinity",
    coloured_sky => "coloured-sky",
    near_object_over_sky => "near-object-over-sky",
    equal_depths => "equal-depths",
    one_pixel => "one-pixel",
    ragged_size => "ragged-size",
    very_wide_image => "very-wide-image",
    degenerate_lens => "degenerate-lens",
    translucent_stack_in_focus => "translucent-stack-in-focus",
    translucent_stack_blurred => "translucent-stack-blurred",
    alpha_0_glow => "alpha-0-glow",
    alpha_0_and_1_in_focus => "alpha-0-and-1-in-focus",
    alpha_out_of_range => "alpha-out-of-range",
    footprint_emitters => "footprint-emitters",
    footprint_coc_extremes => "footprint-coc-extremes",
}
