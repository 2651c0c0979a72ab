#!/usr/bin/env python3
"""poresph's HDF5 checkpoints read with h5py (the users' tool), independently of poresph's reader.

  checkpoint_h5py.py check FILE     the layout the README documents: attributes, the case, every
                                    field with a unit, a float64 position of (particles, dimension),
                                    every particle id once
  checkpoint_h5py.py same A B       the same state: attributes, extras and every field's values and
                                    type (the files' bytes may differ: one process writes through the
                                    POSIX layer, several through MPI-IO; the stored case may differ
                                    in what does not change the state, as the checkpoint interval)
Exit 0 when it holds, 1 with the first difference otherwise.
"""
import sys

import h5py
import numpy as np


def fail(msg):
    print("checkpoint_h5py: " + msg, file=sys.stderr)
    sys.exit(1)


def check(path):
    with h5py.File(path, "r") as f:
        a = f.attrs
        if a["format"] != b"poresph checkpoint" or a["format_version"] != 1:
            fail(f"{path}: format {a.get('format')!r} version {a.get('format_version')!r}")
        n, d = int(a["particles"]), int(a["dimension"])
        for key in ("poresph_version", "case", "precision", "time", "steps", "last_dt", "first_dt"):
            if key not in a:
                fail(f"{path}: no attribute {key}")
        case = f["case"][()].decode()
        if f"name = '{a['case'].decode()}'" not in case:
            fail(f"{path}: the stored case does not name {a['case']!r}")
        for name, ds in f["fields"].items():
            if ds.shape[0] != n or "unit" not in ds.attrs or "description" not in ds.attrs:
                fail(f"{path}: field {name}: shape {ds.shape}, attributes {dict(ds.attrs)}")
        x = f["fields/position"]
        if x.shape != (n, d) or x.dtype != np.float64 or x.attrs["unit"] != b"m":
            fail(f"{path}: position {x.shape} {x.dtype} {x.attrs['unit']!r}")
        ids = np.sort(f["fields/id"][:])
        if f["fields/id"].dtype != np.int32 or len(np.unique(ids)) != n:
            fail(f"{path}: particle ids are not {n} distinct int32")
        float(f["extras/dissipated_energy"][()])
        print(f"{path}: {n} particles, {len(f['fields'])} fields, step {a['steps']}, t = {a['time']} s")


def same(pa, pb):
    with h5py.File(pa, "r") as a, h5py.File(pb, "r") as b:
        if dict(a.attrs) != dict(b.attrs):
            fail(f"attributes differ: {dict(a.attrs)} / {dict(b.attrs)}")
        if list(a["fields"]) != list(b["fields"]):
            fail(f"fields differ: {list(a['fields'])} / {list(b['fields'])}")
        for name in list(a["fields"]):
            x, y = a["fields"][name], b["fields"][name]
            if x.dtype != y.dtype or dict(x.attrs) != dict(y.attrs) or x[:].tobytes() != y[:].tobytes():
                fail(f"{pb}: field {name} differs from {pa}'s")
        for name in ("extras/dissipated_energy", "extras/rigid_bodies"):
            if np.asarray(a[name][()]).tobytes() != np.asarray(b[name][()]).tobytes():
                fail(f"{pb}: {name} differs from {pa}'s")


if __name__ == "__main__":
    if len(sys.argv) == 3 and sys.argv[1] == "check":
        check(sys.argv[2])
    elif len(sys.argv) == 4 and sys.argv[1] == "same":
        same(sys.argv[2], sys.argv[3])
    else:
        fail(__doc__)
