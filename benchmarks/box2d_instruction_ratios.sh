#!/bin/sh
# Instructions per step of the Box2D backend and of the raw Box2D scene, and their ratio (raw /
# backend: the backend's throughput over the raw scene's), for every configuration of
# box2d_benchmark, counted by callgrind over the same steps from the same start (box2d_steps.cpp).
# Usage: box2d_instruction_ratios.sh BUILD_DIR [STEPS]  (prints a Markdown table)
# Without STEPS each configuration takes 60'000 / balls steps (7 minutes in all); STEPS=60 is the
# benchmark's own window, but takes about an hour.
set -eu
steps_binary="$1/benchmarks/box2d_steps"
fixed_steps="${2:-}"

# Instructions of `steps` steps of one world and configuration, from callgrind's summary line.
instructions() {
  valgrind --tool=callgrind --callgrind-out-file=/dev/null --toggle-collect='*timedSteps*' \
    "$steps_binary" "$@" 2>&1 | sed -n 's/.*Collected : //p'
}

echo "| balls | φ | substeps | steps | raw Box2D (M instr./step) | backend (M instr./step) | ratio |"
echo "|---|---|---|---|---|---|---|"
for balls in 1000 2000 5000 10000 20000; do
  # Fewer steps for larger scenes keep each run under a minute; both worlds take the same steps.
  steps=${fixed_steps:-$((60000 / balls))}
  for phi in 5 20 40; do
    for substeps in 1 4; do
      raw=$(instructions raw "$balls" "$phi" "$substeps" "$steps")
      backend=$(instructions backend "$balls" "$phi" "$substeps" "$steps")
      awk -v b="$balls" -v p="$phi" -v s="$substeps" -v n="$steps" -v r="$raw" -v a="$backend" \
        'BEGIN { printf "| %d | 0.%02d | %d | %d | %.1f | %.1f | %.2f× |\n", b, p, s, n, r / n / 1e6, a / n / 1e6, r / a }'
    done
  done
done
