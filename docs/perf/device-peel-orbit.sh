#!/bin/bash
cd "$(dirname "$0")/../.."
for be in cpu vulkan; do for s in 640x360 1280x720 1920x1080; do
 w=${s%x*}; h=${s#*x}
 ./target/debug/dof bench frame --scene fence --method multilayer --orbit 1 --frames 10 --json --backend $be --width $w --height $h > docs/perf/device-peel-orbit/$be-$s.json 2> docs/perf/device-peel-orbit/$be-$s.err
done; done
