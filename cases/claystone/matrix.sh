#!/bin/bash
# shellcheck disable=SC2089,SC2090  # the quotes inside the --set values are TOML's, passed on literally
# The run matrix of Pazdniakou 2018 Table 5 and Deptulski 2021 Ch. 5 on the synthetic claystone
# (cases/claystone_drainage.toml), one `poresph run --set ...` per case, then `poresph report` over
# them all (saturations, porosity, damage, pressures, Pc against S_g and percolation.md, the table of
# percolation times). Confinements in the case's scaled Pa (stress scale 5e7): 10, 8, 6, 4 MPa are
# 0.2, 0.16, 0.12, 0.08 Pa.
#   [JOBS=N] cases/claystone/matrix.sh OUTDIR [reduced|wide|cell] [poresph binary] [extra poresph run options...]
# A case whose run ended, completed or not (OUTDIR/NAME/summary.json), is kept: delete it to run it again.
# reduced: the 16 x 24 x 20 voxel crop of the fracture's upper part (reservoirs of 4 voxels),
#          21,504 particles, to 20 us after percolation (at most 0.5 ms): the size this CPU runs
#          (VALIDATION.md);
# wide:    the 22 x 44 x 15 voxel crop holding the pore's whole width (porosity 0.29; the pore touches
#          no lateral layer), 35,880 particles, to 10 us after percolation: also a CPU size;
# cell:    the whole 50^3 sample (235,480 particles): a GPU size (add --backend cuda).
set -euf  # -f: the [..] of the --set values are not file patterns
out=${1:?usage: matrix.sh OUTDIR [reduced|wide|cell] [poresph] [run options...]}
size=${2:-reduced}
poresph=${3:-poresph}
if [ $# -ge 3 ]; then shift 3; else shift $#; fi
here=$(cd "$(dirname "$0")/.." && pwd)
case=$here/claystone_drainage.toml
case $size in
  reduced) crop="--set sample.image.crop.lower=[16,12,30] --set sample.image.crop.upper=[32,36,50] --set sample.reservoir_height=8e-8
                --set time.end=5e-4 --set time.after_percolation=2e-5 --set output.monitor_interval=2e-6
                --set output.extract_interval=1e-5 --set visualisation.slab.origin=[2.8e-7,3.6e-7,3.7e-7]" ;;
  wide) crop="--set sample.image.crop.lower=[12,4,35] --set sample.image.crop.upper=[34,48,50] --set sample.reservoir_height=8e-8
             --set time.end=5e-4 --set time.after_percolation=1e-5 --set output.monitor_interval=2e-6
             --set output.extract_interval=1e-5 --set visualisation.slab.origin=[3.8e-7,6e-7,3.1e-7]" ;;
  cell) crop="" ;;
  *) echo "matrix.sh: size is reduced, wide or cell, not $size" >&2; exit 2 ;;
esac
# Figure sequences and MP4s of the sections (Pazdniakou Fig. 11, Deptulski Fig. 5.11), rendered in situ.
solid_views="--pipeline phases --pipeline principal_stress --pipeline displacement"
damage_views="$solid_views --pipeline damage"
fields='--set output.fields=["velocity","pressure","material","displacement","principal_stress"]'
# The rigid matrix has no elastic voxels, so no guard beyond its plates.
rigid="--set sample.image.labels.1=plate --set sample.image.labels.2=plate --set sample.lateral_material=plate
       --unset sample.plate_guard_thickness
       --unset sample.confinement --unset sample.confinement_ramp --unset damage --unset solid
       --set output.fields=[\"velocity\",\"pressure\",\"material\"] --pipeline phases"
no_damage="--unset damage $fields $solid_views"
# Deptulski's thermodynamic PCW damage with crack closure (unilateral), beta = eps_u / eps_0 - 1 = 1,
# Y_c0 = E eps_0 eps_u / 2 (the model's defaults with these strains; Deptulski 2021 §5.3).
pcw="--set damage.model=pcw --unset damage.tensile_strength --unset damage.compressive_strength
     --set damage.elastic_limit_strain=0.0013 --set damage.ultimate_strain=0.0026"
jobs=${JOBS:-1}  # runs at once (each with OMP_NUM_THREADS threads, if set); a slot frees when its run ends
run() {  # name, then its --set options; a case that ended (its summary.json) is not run again
  name=$1
  shift
  [ ! -f "$out/$name/summary.json" ] || return 0
  while [ "$(jobs -pr | wc -l)" -ge "$jobs" ]; do wait -n || true; done
  # shellcheck disable=SC2086  # the options are words
  ( "$poresph" run "$case" $crop "$@" --out "$out/$name" --quiet || echo "matrix.sh: $name ended with exit $?" >&2 ) &
}
mkdir -p "$out"
# shellcheck disable=SC2086
run rigid $rigid "$@"
# shellcheck disable=SC2086
run elastic_6MPa $no_damage "$@"
for c in 0.12:6 0.08:4 0.16:8 0.2:10; do
  # shellcheck disable=SC2086
  run "rmc_${c#*:}MPa" $damage_views --set "sample.confinement=${c%:*}" "$@"
done
for c in 0.16:8 0.12:6; do
  # shellcheck disable=SC2086
  run "pcw_${c#*:}MPa" $pcw $damage_views --set "sample.confinement=${c%:*}" "$@"
done
if [ "$size" = cell ]; then  # Deptulski §5.5: two disconnected pores (the reduced crop holds one of them only)
  # shellcheck disable=SC2086
  run pcw_6MPa_two_pores $pcw $damage_views --set sample.image.file=claystone/claystone_two_pores.npy --set sample.confinement=0.12 "$@"
fi
wait
runs=""
for d in rigid elastic_6MPa rmc_10MPa rmc_8MPa rmc_6MPa rmc_4MPa pcw_8MPa pcw_6MPa pcw_6MPa_two_pores; do
  [ -f "$out/$d/monitors.csv" ] && runs="$runs $out/$d"
done
# shellcheck disable=SC2086
"$poresph" report $runs --out "$out/report"
