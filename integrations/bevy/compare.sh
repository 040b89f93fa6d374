#!/usr/bin/env bash
# Bevy's frames against `dof render` of the same view: the headless example renders its scene
# with the plugin and writes the scene and camera as glTF; `dof render` renders that glTF with the
# same lens (single-layer and multi-layer tiled splatting, as the plugin runs them; the pinhole;
# the exact reference), and `dof compare` measures Bevy's images against them (PSNR, SSIM, FLIP).
# Run from anywhere: bash integrations/bevy/compare.sh
set -euo pipefail
cd "$(dirname "$0")"
CARGO_TARGET_DIR="$PWD/target" cargo run --example headless
cd ../..
out=integrations/bevy/out
view=(--scene "$out/bevy-scene.gltf" --width 512 --height 320 --focus 3 --f-number 1 --sensor-height 36 --guard-band off)
for method in pinhole tiled multilayer reference; do
  cargo run --bin dof -- render "${view[@]}" --method "$method" --out "$out/dof-$method.exr"
done
echo "== Bevy's pinhole (the plugin at an infinite f-number) against dof's pinhole"
cargo run --bin dof -- compare "$out/dof-pinhole.exr" "$out/bevy-pinhole.exr"
echo "== Bevy's blurred frame against dof's single-layer tiled splatting of the same view"
cargo run --bin dof -- compare "$out/dof-tiled.exr" "$out/bevy-blurred.exr"
echo "== Bevy's peeled frame (four layers) against dof's multi-layer splatting of the same view"
cargo run --bin dof -- compare "$out/dof-multilayer.exr" "$out/bevy-peeled.exr"
echo "== Bevy's single-layer frame against dof's multi-layer splatting (what the peel adds)"
cargo run --bin dof -- compare "$out/dof-multilayer.exr" "$out/bevy-blurred.exr"
echo "== Bevy's peeled and single-layer frames against the exact reference"
cargo run --bin dof -- compare "$out/dof-reference.exr" "$out/bevy-peeled.exr"
cargo run --bin dof -- compare "$out/dof-reference.exr" "$out/bevy-blurred.exr"
