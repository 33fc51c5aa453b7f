#!/usr/bin/python3
"""Checks run directories written by the C++ writers with independent readers: frames.xdmf must be
well-formed XML whose grids, times and DataItems match frames.h5 (read with h5py), and summary.json
must parse as JSON with the contract's fields. Each frame must hold exactly the datasets of the selected
fields (--fields, the names of [output] fields; default: all) besides position, and the XDMF index must
list exactly those. Usage: check_files.py [--fields NAME,...] RUN_DIR...  (exit 1 on failure)"""
import json
import pathlib
import sys
import xml.etree.ElementTree as ET

import h5py
import numpy as np

ATTRIBUTES = {"velocity": 3, "speed": 1, "sxx": 1, "syy": 1, "szz": 1, "sxy": 1, "p": 1, "q": 1,
              "plastic_strain": 1, "density": 1, "layer": 1, "material": 1}
# [output] fields names -> datasets ("stress" is the four components).
FIELD_DATASETS = {name: [name] for name in ATTRIBUTES if name not in ("sxx", "syy", "szz", "sxy")}
FIELD_DATASETS["stress"] = ["sxx", "syy", "szz", "sxy"]
SUMMARY_FIELDS = {"model": str, "integrator": str, "particles": int, "boundary_particles": int,
                  "steps": int, "threads": int, "end_time": float, "wall_seconds": float,
                  "particle_steps_per_second": float,
                  "runout_m": float, "height_m": float, "repose_angle_deg": float, "max_speed_end": float,
                  "kinetic_energy_end": float, "particle_spacing": float, "smoothing_ratio": float,
                  "time_step": float}
failures = []


def expect(condition, message):
    if not condition:
        failures.append(message)


def check_data_item(item, h5, where):
    if item is None:
        return expect(False, f"{where}: a DataItem is missing")
    file_name, _, path = item.text.strip().partition(":")
    expect(item.get("Format") == "HDF" and file_name == "frames.h5", f"{where}: DataItem {item.text!r}")
    if path not in h5:
        return expect(False, f"{where}: {path} is not in frames.h5")
    data = h5[path]
    dims = tuple(int(d) for d in item.get("Dimensions").split())
    expect(dims == data.shape, f"{where}: {path} has shape {data.shape}, the XDMF says {dims}")
    kind = {"Float": "f", "Int": "i", "UInt": "u"}[item.get("NumberType")]
    expect(data.dtype.kind == kind and data.dtype.itemsize == int(item.get("Precision")),
           f"{where}: {path} is {data.dtype}, the XDMF says {item.get('NumberType')}{item.get('Precision')}")
    return data


def check_run(run, attributes):
    h5 = h5py.File(run / "frames.h5", "r")
    root = ET.parse(run / "frames.xdmf").getroot()  # raises on malformed XML
    expect(root.tag == "Xdmf", "root element is not Xdmf")
    collection = root.find("Domain/Grid")
    expect(collection.get("GridType") == "Collection" and collection.get("CollectionType") == "Temporal",
           "the top grid is not a temporal collection")
    grids = collection.findall("Grid")
    groups = sorted(name for name in h5 if name.startswith("frame_"))
    expect([g.get("Name") for g in grids] == groups, f"XDMF grids {len(grids)} != HDF5 groups {len(groups)}")
    times = []
    for grid in grids:
        name = grid.get("Name")
        times.append(float(grid.find("Time").get("Value")))
        expect(times[-1] == h5[name].attrs["time"], f"{name}: XDMF time != HDF5 attribute")
        n = int(grid.find("Topology").get("NumberOfElements"))
        expect(grid.find("Topology").get("TopologyType") == "Polyvertex", f"{name}: not Polyvertex")
        vertices = check_data_item(grid.find("Topology/DataItem"), h5, name)
        if vertices is not None:
            expect(np.array_equal(vertices[()], np.arange(n)), f"{name}: connectivity is not 0..n-1")
        expect(grid.find("Geometry").get("GeometryType") == "XYZ", f"{name}: geometry is not XYZ")
        position = check_data_item(grid.find("Geometry/DataItem"), h5, name)
        if position is not None:
            expect(position.shape == (n, 3) and np.all(position[:, 2] == 0),
                   f"{name}: position is not N x 3 with z = 0")
        found = {}
        for attribute in grid.findall("Attribute"):
            where = f"{name}/{attribute.get('Name')}"
            found[attribute.get("Name")] = attribute.get("AttributeType")
            expect(attribute.get("Center") == "Node", f"{where}: not node-centred")
            data = check_data_item(attribute.find("DataItem"), h5, name)
            if data is not None:
                expect(data.shape[0] == n, f"{where}: {data.shape[0]} values for {n} points")
        for field, components in attributes.items():
            kind = "Vector" if components == 3 else "Scalar"
            expect(found.get(field) == kind, f"{name}: attribute {field} missing or not {kind}")
        # A frame of a collapse names its particles by their global ids, 0 .. n-1 as built, whatever the
        # fields (frames written from other sources may have none): listed and stored together.
        ids = {"id"} if "id" in h5[name] else set()
        if ids:
            expect(found.get("id") == "Scalar", f"{name}: attribute id missing or not Scalar")
            expect(np.array_equal(h5[name]["id"][()], np.arange(n)), f"{name}: ids are not 0..n-1")
        expect(set(found) == set(attributes) | ids,
               f"{name}: the XDMF lists {sorted(found)}, expected {sorted(set(attributes) | ids)}")
        datasets = set(h5[name])
        expect(datasets == set(attributes) | {"position"} | ids,
               f"{name}: frames.h5 holds {sorted(datasets)}, expected position and {sorted(set(attributes) | ids)}")
        if "velocity" in datasets and "speed" in datasets:
            velocity, speed = h5[name]["velocity"][()], h5[name]["speed"][()]
            expect(np.allclose(np.hypot(velocity[:, 0], velocity[:, 1]), speed, rtol=1e-14, atol=0),
                   f"{name}: speed != |velocity|")
    expect(all(b > a for a, b in zip(times, times[1:])), "frame times do not increase")
    conventions = h5.attrs["conventions"]
    conventions = conventions.decode() if isinstance(conventions, bytes) else conventions
    expect("compression-positive" in conventions, "frames.h5 does not state its sign convention")

    summary = json.loads((run / "summary.json").read_text())
    for field, kind in SUMMARY_FIELDS.items():
        value = summary.get(field)
        ok = isinstance(value, kind) or (kind is float and isinstance(value, int))
        expect(ok and not isinstance(value, bool),
               f"summary.json: {field} = {value!r} is not {kind.__name__}")


arguments = sys.argv[1:]
selected = ATTRIBUTES
if arguments[:1] == ["--fields"]:
    names = [name for name in arguments[1].split(",") if name]
    unknown = [name for name in names if name not in FIELD_DATASETS]
    if unknown:
        sys.exit(f"check_files.py: unknown field names {unknown} (allowed: {', '.join(FIELD_DATASETS)})")
    selected = {d: ATTRIBUTES[d] for name in names for d in FIELD_DATASETS[name]}
    arguments = arguments[2:]
for directory in arguments:
    before = len(failures)
    check_run(pathlib.Path(directory), selected)
    print(f"{directory}: {'ok' if len(failures) == before else 'FAILED'}")
for failure in failures:
    print("FAIL:", failure)
sys.exit(1 if failures or not arguments else 0)
