#!/bin/bash
# before (b20522a binary) vs after (frame API), railing, multilayer 4x4, no guard band
cd /work/main
for be in cpu vulkan; do
for size in "640 360" "1280 720" "1920 1080"; do
  set -- $size
  if [ $be = vulkan ] && [ $1 = 1920 ]; then continue; fi
  echo "== $be $1x$2"
  /usr/bin/time -f "before peak RSS %M KB, wall %e s" /tmp/dof-before render --scene railing --method multilayer --merge 4x4 --backend $be --width $1 --height $2 --guard-band off --out /tmp/before/r.exr 2>&1 | grep -E "splatting on|allocated|peak RSS"
  /usr/bin/time -f "after peak RSS %M KB, wall %e s" target/debug/dof bench frame --backend $be --width $1 --height $2 --frames 3 --json 2>&1
  target/debug/dof bench frame --backend $be --width $1 --height $2 --frames 3 --json --one-shot 2>&1
done
done
