"""Shared building blocks of the poresph Catalyst pipelines (ParaView 5.11, script version 2).

Every pipeline shows the channel "particles" in two views, a 3D view and a cross-section slab
(particles within `slab.half_thickness` of a plane, as in the references' cross-section
figures), and writes one PNG per output step and view into images/<pipeline>/. The settings
(camera, slab, colour maps and fixed colour ranges, folders) come from the JSON file named by
$PORESPH_VIS_SETTINGS, which poresph resolves from the case file at the first output step.
"""
import json
import math
import os

from paraview import catalyst
from paraview.simple import (Calculator, ColorBy, CreateExtractor, CreateView, ExtractSurface,
                             GetColorTransferFunction, GetScalarBar, ProgrammableFilter, Show, Text, Threshold,
                             TrivialProducer)

_state = {"live_taken": False, "slab_extract_taken": False, "time_labels": []}

# The `phase` field (solver/state/derived_fields.hpp): value, label, colour.
SOLID = 3  # the elastic solid's value of the phase field (PHASES)
PHASES = [(0, "wall", [0.55, 0.55, 0.55]), (1, "water", [0.12, 0.47, 0.85]), (2, "gas", [0.98, 0.85, 0.25]),
          (3, "solid", [0.62, 0.42, 0.25]), (4, "rigid", [0.2, 0.2, 0.2])]


TEXT = [0.0, 0.0, 0.0]


def settings():
    path = os.environ.get("PORESPH_VIS_SETTINGS")
    if not path:
        raise RuntimeError("PORESPH_VIS_SETTINGS is not set: poresph names its visualisation settings file there")
    with open(path) as f:
        return json.load(f)


def _camera(view, cam):
    view.CameraPosition = cam["position"]
    view.CameraFocalPoint = cam["focal_point"]
    view.CameraViewUp = cam["view_up"]
    view.CameraViewAngle = cam.get("view_angle", 30.0)
    if cam.get("parallel_scale"):
        view.CameraParallelProjection = 1
        view.CameraParallelScale = cam["parallel_scale"]


def _view(s, cam):
    v = CreateView("RenderView")
    v.ViewSize = s["image_size"]
    v.OrientationAxesVisibility = 0
    v.UseFXAA = 0  # deterministic images for the regression tests
    v.Background = [1.0, 1.0, 1.0]
    v.UseColorPaletteForBackground = 0
    _camera(v, cam)
    if s.get("time_label", True):
        # A Text source set in catalyst_execute: AnnotateTime clashes with Catalyst's own "time"
        # formatter argument and warns at every frame.
        text = Text(registrationName="time_label_%d" % len(_state["time_labels"]))
        label = Show(text, v)
        label.Color = TEXT
        label.FontSize = 14
        label.WindowLocation = "Upper Left Corner"
        _state["time_labels"].append(text)
    return v


def _processes():
    from paraview import servermanager
    return servermanager.vtkProcessModule.GetProcessModule().GetNumberOfLocalPartitions()


_CORNERS = """
from vtkmodules.vtkCommonCore import vtkPoints
from vtkmodules.vtkCommonDataModel import vtkCellArray
b = %r
points = vtkPoints()
points.InsertNextPoint(b[0], b[2], b[4])
points.InsertNextPoint(b[1], b[3], b[5])
verts = vtkCellArray()
for k in range(2):
    verts.InsertNextCell(1)
    verts.InsertCellPoint(k)
out = self.GetPolyDataOutput()
out.SetPoints(points)
out.SetVerts(verts)
"""


def _span_the_scene(source, view, s):
    """ParaView crops each process's image to the bounds of its representations' data, and a
    sphere reaches a radius past its particle: two points at the corners of the scene padded by
    that radius, on every process, one pixel each in the background's colour, make every
    process's image whole."""
    corners = ProgrammableFilter(Input=source)
    corners.OutputDataSetType = "vtkPolyData"
    corners.Script = _CORNERS % (s["bounds"],)
    d = Show(corners, view)
    d.SetRepresentationType("Points")
    d.PointSize = 1
    d.AmbientColor = d.DiffuseColor = list(view.Background)


def _pixels_per_metre(view):
    """At the focal point: the view's height in pixels over its height in metres."""
    if view.CameraParallelProjection:
        height = 2 * view.CameraParallelScale
    else:
        d = math.dist(view.CameraPosition, view.CameraFocalPoint)
        height = 2 * d * math.tan(math.radians(view.CameraViewAngle) / 2)
    return view.ViewSize[1] / height


def _particles_display(source, view, s):
    d = Show(source, view)
    if _processes() > 1:
        # Point Gaussian splats are composited in the order of regions ParaView redistributes the
        # particles into, each cut at its region's bounds: over several processes, sphere-shaded
        # points of the same size in pixels (at the focal point), composited by depth.
        d.SetRepresentationType("Points")
        d.RenderPointsAsSpheres = 1
        d.PointSize = max(1.0, 2 * s["point_radius"] * _pixels_per_metre(view))
        _span_the_scene(source, view, s)
        return d
    d.SetRepresentationType("Point Gaussian")
    d.ShaderPreset = "Sphere"
    d.GaussianRadius = s["point_radius"]
    return d


def _categories(lut, categorical):
    lut.InterpretValuesAsCategories = 1
    lut.Annotations = [str(x) for pair in categorical for x in (pair[0], pair[1])]
    lut.IndexedColors = [c for pair in categorical for c in pair[2]]
    return lut


def _lut(field, s, categorical=None, above_range=None):
    lut = GetColorTransferFunction(field)
    lut.AutomaticRescaleRangeMode = "Never"  # ranges stay fixed over a run
    if categorical:
        return _categories(lut, categorical)
    lut.ApplyPreset(s["colour_maps"].get(field, "Viridis (matplotlib)"), True)
    lo, hi = s["ranges"][field]
    lut.RescaleTransferFunction(lo, hi)
    if above_range:
        lut.UseAboveRangeColor = 1
        lut.AboveRangeColor = above_range
    return lut


def _colour(display, view, field, component, lut, s, has_field):
    if not has_field:
        # The case has no such field (its physics is not active): plain grey particles.
        ColorBy(display, None)
        display.AmbientColor = display.DiffuseColor = [0.7, 0.7, 0.7]
        return
    if component is None:
        ColorBy(display, ("POINTS", field))
    else:
        ColorBy(display, ("POINTS", field, component))
        lut.VectorMode = "Component"
        lut.VectorComponent = {"X": 0, "Y": 1, "Z": 2}[component]
    display.LookupTable = lut
    if field in s["ranges"]:  # again: ColorBy may have rescaled to the data
        lut.AutomaticRescaleRangeMode = "Never"
        lut.RescaleTransferFunction(*s["ranges"][field])
    if s.get("scalar_bar", True):
        display.SetScalarBarVisibility(view, True)
        bar = GetScalarBar(lut, view)
        bar.Title = s.get("titles", {}).get(field, field)
        bar.ComponentTitle = ""
        bar.TitleColor = bar.LabelColor = TEXT  # the default palette's text is white
        bar.RangeLabelFormat = "%-#.3g"
        bar.WindowLocation = "Any Location"  # the right 20 % of the image (vis_settings frames the scene)
        bar.Position = [0.84, 0.1]
        bar.ScalarBarLength = 0.8
        bar.TitleFontSize = bar.LabelFontSize = max(8, min(16, s["image_size"][1] // 38))  # 16 at 600 px


def _phase_colours(display):
    """The phases' colours (PHASES), without a scalar bar: the context of a solid field."""
    ColorBy(display, ("POINTS", "phase"))
    display.LookupTable = _categories(GetColorTransferFunction("phase_context"), PHASES)


def _png(view, name, prefix, s):
    png = CreateExtractor("PNG", view, registrationName="%s_%s_png" % (name, prefix))
    png.Writer.FileName = prefix + "_{timestep:06d}.png"
    png.Writer.ImageResolution = s["image_size"]
    png.Writer.OverrideColorPalette = ""
    return png


def slab(source, s):
    """Particles within slab.half_thickness of the slab plane."""
    o, n, h = s["slab"]["origin"], s["slab"]["normal"], s["slab"]["half_thickness"]
    dist = Calculator(registrationName="slab_distance", Input=source)
    dist.ResultArrayName = "slab_distance"
    dist.Function = "abs((coordsX-(%r))*(%r)+(coordsY-(%r))*(%r)+(coordsZ-(%r))*(%r))" % (
        o[0], n[0], o[1], n[1], o[2], n[2])
    return _between(dist, "slab_distance", 0.0, h, "slab")


def _between(source, array, lo, hi, name, invert=False):
    """The particles whose `array` lies in [lo, hi] (outside it with `invert`)."""
    t = Threshold(registrationName=name, Input=source)
    t.Scalars = ["POINTS", array]
    t.LowerThreshold = lo
    t.UpperThreshold = hi
    t.ThresholdMethod = "Between"
    t.Invert = 1 if invert else 0
    return t


def _solid(source, name, others=False):
    """The elastic solid's particles (the others with `others`)."""
    return _between(source, "phase", SOLID - 0.5, SOLID + 0.5, name, invert=others)


def field_pipeline(name, field, component=None, categorical=None, above_range=None, solid_field=False,
                   shown_above=None):
    """A pipeline colouring the particles by `field` (a component of it when given) in a 3D view
    and a slab view. `categorical`: [(value, label, [r, g, b]), ...] for an indexed colour map.
    `solid_field`: a field of the elastic solid (damage, its stress, its displacement): only the
    solid takes the field's colours, the other particles their phase's (Pazdniakou 2018 Fig. 11),
    and the 3D view shows the solid alone; `shown_above`: only where the field exceeds it (the
    damaged points, D > 1e-3, Pazdniakou's count), so that the undamaged solid hides nothing.
    Returns the catalyst Options the script must expose as `options`."""
    s = settings()
    particles = TrivialProducer(registrationName="particles")
    lut = _lut(field, s, categorical, above_range)
    has_phase = "phase" in particles.PointData.keys()
    has_field = field in particles.PointData.keys()  # asked of the input: a threshold's output may be empty
    solid_field = solid_field and has_phase
    shown = particles
    if solid_field:
        shown = _solid(particles, "solid")
        if shown_above is not None and s["dimension"] == 3 and has_field:
            shown = _between(shown, field, shown_above, 1e300, "above")
    elif s["dimension"] == 3 and not s.get("show_walls", False) and has_phase:
        # Walls would hide the inside of a closed domain in 3D; the slab shows them.
        shown = _between(particles, "phase", 0.5, 100.0, "not_walls")
    views = [("3d", shown, s["camera"], None)]
    if s["dimension"] == 3:
        cut = slab(particles, s)
        if solid_field:
            views.append(("slab", _solid(cut, "slab_solid"), s["slab"]["camera"], _solid(cut, "slab_others", True)))
        else:
            views.append(("slab", cut, s["slab"]["camera"], None))
    elif solid_field:  # 2D: the whole plane is the section
        views[0] = ("3d", shown, s["camera"], _solid(particles, "others", True))
    for prefix, source, cam, others in views:
        view = _view(s, cam)
        _colour(_particles_display(source, view, s), view, field, component, lut, s, has_field)
        if others is not None:
            _phase_colours(_particles_display(others, view, s))
        _png(view, name, prefix, s)
    if s["dimension"] == 3 and s.get("slab_extract", True) and not _state["slab_extract_taken"]:
        _state["slab_extract_taken"] = True  # one slab extract per run, whichever pipeline comes first
        vtp = CreateExtractor("VTP", ExtractSurface(Input=cut), registrationName="slab_vtp")  # every phase
        vtp.Writer.FileName = os.path.join(s["extracts_dir"], "slab_{timestep:06d}.pvtp")
        vtp.Writer.DataMode = "Binary"  # inline: see solver/io/particle_output.cpp

    return live_options(s, os.path.join(s["images_dir"], name))


def live_options(s=None, folder=None):
    """Catalyst options: every call is an output step (poresph decides when), images under
    images/, and ParaView Live on the first pipeline when the run was given --live."""
    s = s or settings()
    options = catalyst.Options()
    options.ExtractsOutputDirectory = folder or s["images_dir"]
    options.GlobalTrigger.Frequency = 1
    if s.get("live_url") and not _state["live_taken"]:
        _state["live_taken"] = True  # one Live connection per run
        options.EnableCatalystLive = 1
        options.CatalystLiveURL = s["live_url"]
    return options


def catalyst_execute(info):
    """Called by Catalyst at each output step before the extracts are written."""
    for text in _state["time_labels"]:
        text.Text = "t = %.4g s" % info.time
