#!/bin/bash
# In-situ figures of a run over two processes (`mpirun -n 2 poresph run --pipeline ...`): every
# process hands its piece to Catalyst on its render thread, ParaView composites the images; every
# frame is drawn (none dropped), the pictures are those of one process's run, and the pipeline's
# slab extracts hold the same particles.
# The threshold: one process draws Point Gaussian splats, several draw sphere-shaded points of the
# same size (poresph_views.py says why): vtkTesting difference up to 2.7 (2D channel flow); a process's
# piece cropped at its bounds measured 2,400 to 4,700.
# Usage: insitu_shared_run.sh PORESPH MPIEXEC IMAGE_DIFF SRC WORK
set -u
poresph=$(realpath "$1") mpiexec=$2 image_diff=$(realpath "$3") src=$(realpath "$4") work=$5
rm -rf "$work" && mkdir -p "$work" && cd "$work" || exit 1
fail() { echo "in-situ shared run: $*" >&2; exit 1; }
export OMP_NUM_THREADS=1 OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1 OMPI_MCA_rmaps_base_oversubscribe=1 OMPI_MCA_mpi_yield_when_idle=1

# The case on one process (one/) and on two (two/), every frame drawn: the frames' count, none dropped.
pair() {  # case, end time, folder
  local sets=(--set "time.end=$2" --set visualisation.every_frame=true --quiet)
  mkdir -p "$3" && cd "$3" || exit 1
  "$poresph" run "$src/cases/$1.toml" --out one --pipeline phases "${sets[@]}" > one.out 2>&1 ||
    fail "$1 on one process failed: $(tail -5 one.out)"
  "$mpiexec" -n 2 "$poresph" run "$src/cases/$1.toml" --out two --pipeline phases "${sets[@]}" > two.out 2>&1 ||
    fail "$1 on 2 processes failed: $(tail -5 two.out)"
  frames=$(($(wc -l < two/images/frames.csv) - 1))
  [ "$frames" -gt 2 ] && [ "$frames" = $(($(wc -l < one/images/frames.csv) - 1)) ] ||
    fail "$1: $frames frames on 2 processes, $(($(wc -l < one/images/frames.csv) - 1)) on one"
  grep -q '"dropped_frames": 0' two/summary.json || fail "$1: frames dropped on 2 processes"
  last=$(printf "%06d" $((frames - 1)))
  for view in 3d slab; do
    [ -e "one/images/phases/${view}_$last.png" ] || continue  # (2D cases have no slab view)
    "$image_diff" "$PWD/two/images/phases/${view}_$last.png" "$PWD/one/images/phases/${view}_$last.png" "$PWD/diff" 10 \
      > "$view.diff" || fail "$1: the $view view of 2 processes differs from one process's: $(grep 'image difference' "$view.diff")"
  done
  echo "$1 on 2 processes: $frames frames, none dropped; views as one process's ($(cat ./*.diff | grep -o 'image difference [0-9.e+-]*' | tr '\n' ' '))"
  cd ..
}
pair poiseuille_2d 0.02 channel     # large spheres: a cropped piece would show
pair dam_break_3d 0.004 dam_break   # 3D: the slab view and its extracts
cd dam_break || exit 1
/usr/bin/python3 - "one/extracts/slab_$last.pvtp" "two/extracts/slab_$last.pvtp" <<'PY' || fail "the slab extracts differ"
import sys
import numpy as np
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOXML import vtkXMLGenericDataObjectReader
def points(path):
    r = vtkXMLGenericDataObjectReader()
    r.SetFileName(path)
    r.Update()
    x = vtk_to_numpy(r.GetOutput().GetPoints().GetData())
    return x[np.lexsort(x.T)]
a, b = points(sys.argv[1]), points(sys.argv[2])
sys.exit(0 if len(a) > 0 and np.array_equal(a, b) else 1)
PY
echo "slab extracts of 2 processes: the same particles as one process's"
