// An interactive view of one particle extract (VTP, VTU or their parallel sets) with vtk.js: rotate and zoom with the mouse,
// colour by any point field (vectors by magnitude), hide phases (by the material field), and keep
// only a slab across one axis.
import '@kitware/vtk.js/Rendering/Profiles/Geometry';
import vtkGenericRenderWindow from '@kitware/vtk.js/Rendering/Misc/GenericRenderWindow';
import vtkPolyData from '@kitware/vtk.js/Common/DataModel/PolyData';
import vtkDataArray from '@kitware/vtk.js/Common/Core/DataArray';
import vtkActor from '@kitware/vtk.js/Rendering/Core/Actor';
import vtkMapper from '@kitware/vtk.js/Rendering/Core/Mapper';
import vtkColorTransferFunction from '@kitware/vtk.js/Rendering/Core/ColorTransferFunction';
import vtkColorMaps from '@kitware/vtk.js/Rendering/Core/ColorTransferFunction/ColorMaps';
import { number } from './format.js';
import { readExtract } from './extract_reader.js';

const PRESETS = { damage: 'Inferno (matplotlib)', colour: 'Blue Orange (divergent)', pressure: 'Viridis (matplotlib)' };

export class View3D {
  constructor(container, legend) {
    this.legend = legend;
    this.grw = vtkGenericRenderWindow.newInstance({ background: [0.125, 0.14, 0.17] });
    this.grw.setContainer(container);
    this.grw.resize();
    this.renderer = this.grw.getRenderer();
    this.mapper = vtkMapper.newInstance({ interpolateScalarsBeforeMapping: false });
    this.actor = vtkActor.newInstance();
    this.actor.setMapper(this.mapper);
    this.renderer.addActor(this.actor);
    this.lut = vtkColorTransferFunction.newInstance();
    this.mapper.setLookupTable(this.lut);
    this.points = null;
    this.fields = {};
    this.field = '';
    this.hidden = new Set();
    this.slab = { on: false, axis: 2, position: 0.5, width: 0.1 };
    this.url = '';
    window.addEventListener('resize', () => this.grw.resize());
  }

  async load(url) {
    const extract = await readExtract(url);
    const first = !this.points;
    this.points = extract.points;
    this.fields = extract.fields;
    this.bounds = extract.bounds;
    this.url = url;
    if (!(this.field in this.fields)) this.field = 'pressure' in this.fields ? 'pressure' : Object.keys(this.fields)[0] || '';
    this.update();
    if (first) this.resetCamera();
    return Object.keys(this.fields);
  }

  materials() {
    const m = this.fields.material;
    return m ? [...new Set(m.values)].sort((a, b) => a - b) : [];
  }

  // Value of the colouring field at point i (magnitude for vectors and tensors).
  value(f, i) {
    if (f.components === 1) return f.values[i];
    let s = 0;
    for (let c = 0; c < f.components; c += 1) s += f.values[i * f.components + c] ** 2;
    return Math.sqrt(s);
  }

  update() {
    if (!this.points) return;
    const n = this.points.length / 3;
    const f = this.fields[this.field];
    const mat = this.fields.material;
    const b = this.bounds;
    const ax = this.slab.axis;
    const lo = b[2 * ax] + (b[2 * ax + 1] - b[2 * ax]) * (this.slab.position - this.slab.width / 2);
    const hi = lo + (b[2 * ax + 1] - b[2 * ax]) * this.slab.width;
    const keep = [];
    let vmin = Infinity;
    let vmax = -Infinity;
    for (let i = 0; i < n; i += 1) {
      if (f) {
        const v = this.value(f, i);
        if (v < vmin) vmin = v;
        if (v > vmax) vmax = v;
      }
      if (mat && this.hidden.has(mat.values[i])) continue;
      if (this.slab.on) {
        const x = this.points[3 * i + ax];
        if (x < lo || x > hi) continue;
      }
      keep.push(i);
    }
    const pts = new Float32Array(3 * keep.length);
    const scalars = new Float32Array(keep.length);
    const verts = new Uint32Array(2 * keep.length);
    keep.forEach((i, k) => {
      pts.set(this.points.subarray(3 * i, 3 * i + 3), 3 * k);
      scalars[k] = f ? this.value(f, i) : 0;
      verts[2 * k] = 1;
      verts[2 * k + 1] = k;
    });
    const pd = vtkPolyData.newInstance();
    pd.getPoints().setData(pts, 3);
    pd.getVerts().setData(verts);
    pd.getPointData().setScalars(vtkDataArray.newInstance({ name: this.field || 'none', values: scalars }));
    if (!(vmax > vmin)) vmax = vmin + 1;
    this.lut.applyColorMap(vtkColorMaps.getPresetByName(PRESETS[this.field] || 'Viridis (matplotlib)'));
    this.lut.setMappingRange(vmin, vmax);
    this.lut.updateRange();
    this.mapper.setScalarRange(vmin, vmax);
    this.mapper.setInputData(pd);
    this.actor.getProperty().setPointSize(Math.max(2, Math.min(8, Math.round(500 / Math.sqrt(n)))));
    this.legend.textContent = f ? `${this.field}: ${number(vmin)} … ${number(vmax)} · ${keep.length} of ${n} particles` : '';
    this.legend.dataset.field = this.field;
    this.grw.getRenderWindow().render();
  }

  resetCamera() {
    const b = this.bounds;
    const flat = b[5] - b[4] < 1e-12 * Math.max(b[1] - b[0], b[3] - b[2], 1e-30);
    const cam = this.renderer.getActiveCamera();
    cam.setParallelProjection(flat);
    if (flat) {
      cam.setPosition((b[0] + b[1]) / 2, (b[2] + b[3]) / 2, 1);
      cam.setFocalPoint((b[0] + b[1]) / 2, (b[2] + b[3]) / 2, 0);
      cam.setViewUp(0, 1, 0);
    }
    this.renderer.resetCamera();
    this.grw.getRenderWindow().render();
  }

  setField(name) {
    this.field = name;
    this.update();
  }

  setHidden(material, hidden) {
    if (hidden) this.hidden.add(material);
    else this.hidden.delete(material);
    this.update();
  }

  setSlab(slab) {
    Object.assign(this.slab, slab);
    this.update();
  }
}
