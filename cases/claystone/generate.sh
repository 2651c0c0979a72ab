#!/bin/sh
# Regenerates the synthetic claystone samples of this folder (labels 0 pore, 1 clay matrix,
# 2 mineral grain; 50^3 voxels, seed 1; solver/image/claystone_sample.hpp):
#   claystone_one_pore.npy   one fracture-like pore percolating along z (wide entry at the top,
#                            narrow outlet at the bottom) among small disconnected pores
#   claystone_two_pores.npy  Deptulski 2021 §5.5's variant: two disconnected pores, tips to either side
# Usage: cases/claystone/generate.sh [poresph binary]   (tests/test_claystone.cpp checks they match)
set -eu
poresph=${1:-poresph}
here=$(dirname "$0")
for variant in one_pore two_pores; do
  "$poresph" image generate claystone --variant "$variant" --seed 1 --size 50 --out "$here/claystone_$variant.npy"
done
