#!/usr/bin/env python3
"""Two runs' particle extracts hold the same particles, in the same order, with the same values,
whatever their files: one .vtp or .vtu per time, or a .pvtp or .pvtu and its pieces (a run over
several processes). Read through VTK's own readers (ParaView's Python modules).

  compare_extracts.py RUN_A RUN_B [FORMAT]    FORMAT: what RUN_B's files must be (vtp, pvtp, vtu, pvtu)
Each extract must say the run's precision (field data "precision"). Exit 0 when they agree, 1 with the first difference otherwise.
"""
import os
import re
import sys

from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOXML import vtkXMLGenericDataObjectReader


def fail(msg):
    print("compare_extracts: " + msg, file=sys.stderr)
    sys.exit(1)


def listed(run):
    with open(os.path.join(run, "extracts", "particles.pvd")) as f:
        entries = re.findall(r'timestep="([^"]*)" file="([^"]*)"', f.read())
    if not entries:
        fail(f"{run}: no extract listed in particles.pvd")
    return entries


def arrays(path):
    r = vtkXMLGenericDataObjectReader()
    r.SetFileName(path)
    r.Update()
    d = r.GetOutput()
    if d is None or d.GetNumberOfPoints() == 0:
        fail(f"{path}: no particles read")
    out = {"Points": vtk_to_numpy(d.GetPoints().GetData())}
    pd = d.GetPointData()
    for k in range(pd.GetNumberOfArrays()):
        out[pd.GetArrayName(k)] = vtk_to_numpy(pd.GetArray(k))
    precision = d.GetFieldData().GetAbstractArray("precision")
    if precision is None or precision.GetValue(0) not in ("double", "mixed", "single"):
        fail(f"{path}: no field data 'precision' naming the run's precision")
    out["precision"] = precision.GetValue(0)
    return d.GetClassName(), d.GetNumberOfCells(), out


def main(a, b, form=None):
    la, lb = listed(a), listed(b)
    if [t for t, _ in la] != [t for t, _ in lb]:
        fail(f"extract times differ: {la} / {lb}")
    for (t, fa), (_, fb) in zip(la, lb):
        if form and not fb.endswith("." + form):
            fail(f"{b}: {fb} is not a .{form} file")
        ka, ca, xa = arrays(os.path.join(a, "extracts", fa))
        kb, cb, xb = arrays(os.path.join(b, "extracts", fb))
        if sorted(xa) != sorted(xb):
            fail(f"t = {t}: fields {sorted(xa)} / {sorted(xb)}")
        if xa.pop("precision") != xb.pop("precision"):
            fail(f"t = {t}: {fb} and {fa} were written in other precisions")
        for name in xa:
            if xa[name].shape != xb[name].shape or xa[name].tobytes() != xb[name].tobytes():
                fail(f"t = {t}: {fb}'s {name} differs from {fa}'s")
        if cb != len(xb["Points"]):
            fail(f"{fb}: {cb} cells for {len(xb['Points'])} particles (expected one vertex each)")
    print(f"{len(la)} extracts of {b} hold {a}'s particles")


if __name__ == "__main__":
    if len(sys.argv) not in (3, 4):
        fail(__doc__)
    main(*sys.argv[1:])
