// A particle extract as points and point fields, whatever its file: a .vtp, a .vtu (vertex cells:
// read as the polydata it is), or a .pvtp/.pvtu and its pieces (a run over several processes),
// the pieces joined in their order.
import vtkXMLPolyDataReader from '@kitware/vtk.js/IO/XML/XMLPolyDataReader';

async function fetched(url) {
  const r = await fetch(url);
  if (!r.ok) throw new Error(`${url}: HTTP ${r.status}`);
  return r.arrayBuffer();
}

// An unstructured grid of vertex cells, inline-encoded, rewritten as the same points in a polydata
// document (its cells are dropped: one vertex per point is implied).
function gridAsPolyData(buffer) {
  const text = new TextDecoder().decode(buffer)
    .replace('type="UnstructuredGrid"', 'type="PolyData"')
    .replace('<UnstructuredGrid>', '<PolyData>')
    .replace('</UnstructuredGrid>', '</PolyData>')
    .replace(/<Cells>[\s\S]*?<\/Cells>/, '')
    .replace(/NumberOfCells="\d+"/, 'NumberOfVerts="0" NumberOfLines="0" NumberOfStrips="0" NumberOfPolys="0"');
  return new TextEncoder().encode(text).buffer;
}

async function readPiece(url) {
  let buffer = await fetched(url);
  if (url.endsWith('.vtu')) buffer = gridAsPolyData(buffer);
  const reader = vtkXMLPolyDataReader.newInstance();
  reader.parseAsArrayBuffer(buffer);
  const pd = reader.getOutputData(0);
  const fields = {};
  const data = pd.getPointData();
  for (let k = 0; k < data.getNumberOfArrays(); k += 1) {
    const a = data.getArrayByIndex(k);
    fields[a.getName()] = { values: a.getData(), components: a.getNumberOfComponents() };
  }
  return { points: pd.getPoints().getData(), fields };
}

// The pieces a .pvtp or .pvtu lists, as URLs beside it.
async function pieceUrls(url) {
  const text = new TextDecoder().decode(await fetched(url));
  const base = url.slice(0, url.lastIndexOf('/') + 1);
  const sources = [...text.matchAll(/<Piece\s+Source="([^"]+)"/g)].map((m) => base + m[1]);
  if (sources.length === 0) throw new Error(`${url}: no pieces listed`);
  return sources;
}

function joined(arrays) {
  const out = new arrays[0].constructor(arrays.reduce((s, a) => s + a.length, 0));
  let at = 0;
  for (const a of arrays) {
    out.set(a, at);
    at += a.length;
  }
  return out;
}

export async function readExtract(url) {
  const parallel = /\.pvt[pu]$/.test(url);
  const pieces = await Promise.all((parallel ? await pieceUrls(url) : [url]).map(readPiece));
  const fields = {};
  for (const name of Object.keys(pieces[0].fields)) {
    fields[name] = { values: joined(pieces.map((p) => p.fields[name].values)), components: pieces[0].fields[name].components };
  }
  const points = joined(pieces.map((p) => p.points));
  const bounds = [Infinity, -Infinity, Infinity, -Infinity, Infinity, -Infinity];
  for (let i = 0; i < points.length; i += 1) {
    const k = 2 * (i % 3);
    if (points[i] < bounds[k]) bounds[k] = points[i];
    if (points[i] > bounds[k + 1]) bounds[k + 1] = points[i];
  }
  return { points, fields, bounds };
}
