#!/usr/bin/env bash
# boreas: whether PoCL vectorized each hot kernel's work-item loop, and at what width.
# Compiles each kernel afresh (no PoCL or boreas binary cache) with PoCL's LLVM remarks on,
# by running its benchmark briefly, and prints one line per kernel.
#   usage: bench/check-vectorization.sh [path/to/boreas_bench]   (default build/bench/...)
# BOREAS_KERNEL_DIR works as usual, to check edited kernels without rebuilding.
set -euo pipefail

bench=${1:-build/bench/boreas_bench}
if [[ ! -x $bench ]]; then
  echo "no benchmark program at $bench: build the boreas_bench target, or pass its path" >&2
  exit 1
fi

# kernel name, then a benchmark that launches it (small sizes: only the compile matters).
checks=(
  "boreas_wind_sample_points BM_WindSineSum/cl/65536/"
  "boreas_wind_sine_slab BM_WindSineSlab/cl/65536/"
  "boreas_wind_grid_step BM_WindGridStep/cl/16384/"
  "boreas_wind_forcing_field BM_WindGridStep/cl/16384/"
  "boreas_bandwidth_copy BM_CopyBandwidth/cl/1048576/"
  "boreas_tree_step BM_TreeStep/cl/65536/lagged"
  "boreas_tree_deform BM_Deform/cl/65536/"
  "boreas_tree_leaves BM_TreeLeaves/cl/65536/"
  "boreas_tile_copy BM_ForestStep/mixed/1000/1M/lod"
  "boreas_underbrush_step BM_UnderbrushStep/cl/65536/"
  "boreas_underbrush_vertices BM_UnderbrushVertices/cl/65536/"
  "boreas_mesh_tree_branches BM_MeshTree/cl/4576/"
  "boreas_mesh_tree_trunk BM_MeshTree/cl/4576/"
  "boreas_mesh_tree_leaves BM_MeshTree/cl/4576/"
  "boreas_blobtree_field BM_BlobTreeField/cl/2097152/binned"
  "boreas_blobtree_field_naive BM_BlobTreePolygonize/cl/2097152/naive"
  "boreas_blobtree_count BM_BlobTreePolygonize/cl/2097152/binned"
  "boreas_blobtree_emit BM_BlobTreePolygonize/cl/2097152/binned"
  "boreas_blobtree_attributes BM_BlobTreePolygonize/cl/2097152/binned"
)

for check in "${checks[@]}"; do
  read -r kernel filter <<<"$check"
  # PoCL prints remarks without line breaks, each starting "<unknown>:0:0: ".
  remarks=$(POCL_VECTORIZER_REMARKS=1 POCL_KERNEL_CACHE=0 BOREAS_CACHE_DIR= \
              "$bench" --benchmark_filter="$filter" --benchmark_min_time=0.01 2>&1 |
            sed 's/<unknown>:0:0: /\n/g')
  # The work-item loops exist only in the work-group function PoCL generates at the first
  # launch; its remarks follow the line that inlines the kernel into it. Earlier remarks
  # (the program build) are about loops inside one work-item.
  wg=$(printf '%s\n' "$remarks" |
       awk -v k="'_pocl_kernel_${kernel}' inlined into '_pocl_kernel_${kernel}_workgroup" '
         index($0, k) { on = 1; next }
         on && /_pocl_kernel_/ && !index($0, "_pocl_kernel_" kname) { on = 0 }
         on { print }' kname="$kernel")
  width=$(printf '%s\n' "$wg" | sed -n 's/.*vectorized loop (vectorization width: \([0-9]*\).*/\1/p' |
          sort -n | tail -1)
  vectorized=$(printf '%s\n' "$wg" | grep -c '^vectorized loop (' || true)
  # A loop that is not vectorized gets a line with the reason, then a bare one.
  missed=$(printf '%s\n' "$wg" | grep -c '^loop not vectorized$' || true)
  reasons=$(printf '%s\n' "$wg" | sed -n 's/^loop not vectorized: \(.*\)/\1/p' | sort -u |
            paste -sd ';' | sed 's/;/; /g')
  if [[ -z $wg ]]; then
    echo "$kernel: NOT vectorized: no remarks seen (did its benchmark run? try it by hand)"
  elif [[ $vectorized -gt 0 && $missed -eq 0 ]]; then
    echo "$kernel: vectorized width $width"
  elif [[ $vectorized -gt 0 ]]; then
    echo "$kernel: PARTLY vectorized: width $width in $vectorized of $((vectorized + missed))" \
         "loops; the others not: ${reasons:-no reason given}"
  else
    echo "$kernel: NOT vectorized: ${reasons:-no reason given}"
  fi
done
