"""CPU time per frame by kernel group from a `perf record` of `dof bench frame` on the CPU
backend (docs/measurements.md, "The CPU backend at 1920x1080"): perf-by-kernel.py DATA HZ FRAMES,
FRAMES counting the warm-up frames too. Samples of cpu-clock at HZ are CPU time, so the figures
hold on a shared machine where the wall clock does not."""
import sys, re, subprocess
data, freq, frames = sys.argv[1], float(sys.argv[2]), float(sys.argv[3])
out = subprocess.run(["perf", "report", "-i", data, "--no-children", "--stdio", "--sort", "sym", "-n"], capture_output=True, text=True).stdout
groups = {}
def group(sym):
    if "accumulate" in sym or "shaped_weight" in sym or "weight_sum" in sym: return "accumulate"
    if "splat::bin" in sym: return "bin+count+compact"
    if "dof_shaders::sort" in sym: return "sort"
    if "merge" in sym or "pack" in sym or "Fragment>::store" in sym: return "pack+merge"
    if "dof_shaders" in sym: return "other kernels"
    return "not kernels (setup, scene, kernel, rayon)"
for line in out.splitlines():
    m = re.match(r"\s+([\d.]+)%\s+(\d+)\s+\[.\]\s+(.*)", line)
    if m:
        g = group(m.group(3)); groups[g] = groups.get(g, 0) + int(m.group(2))
tot = 0
for g, n in sorted(groups.items()):
    cs = n / freq / frames
    if not g.startswith("not"): tot += cs
    print(f"{g:45s} {cs:7.3f} CPU-s per frame")
print(f"{'kernels in all':45s} {tot:7.3f} CPU-s per frame")
