"""Batch re-rendering for `poresph figures`: feeds a run's particle extracts, in order, to the same
Catalyst pipeline scripts the run used, as if they came from the solver (frame k = extract k).

    pvbatch render_extracts.py EXTRACT_LIST_FILE SCRIPT [SCRIPT ...]

$PORESPH_VIS_SETTINGS names the run's images/visualisation.json.
"""
import sys

from paraview.catalyst import bridge
from vtkmodules.vtkFiltersGeometry import vtkGeometryFilter
from vtkmodules.vtkIOXML import vtkXMLGenericDataObjectReader


def particles(path):
    """An extract as the solver hands it to Catalyst: polydata of vertices (a .vtu, a .pvtp or a
    .pvtu of a run over several processes read whole, its pieces in order)."""
    reader = vtkXMLGenericDataObjectReader()
    reader.SetFileName(path)
    reader.Update()
    data = reader.GetOutputDataObject(0)
    if data.IsA("vtkPolyData"):
        return data
    geometry = vtkGeometryFilter()
    geometry.SetInputData(data)
    geometry.Update()
    return geometry.GetOutputDataObject(0)


def main(list_file, scripts):
    with open(list_file) as f:
        frames = [line.rstrip("\n").split("\t") for line in f if line.strip()]
    bridge.initialize()
    for s in scripts:
        bridge.add_pipeline(s, 2)
    for k, (time, path) in enumerate(frames):
        bridge.coprocess(float(time), k, particles(path), name="particles")
    bridge.finalize()


if __name__ == "__main__":
    main(sys.argv[1], sys.argv[2:])
