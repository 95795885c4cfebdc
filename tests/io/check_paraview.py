"""Opens a run's files in ParaView as a user would and checks what it shows
(docs/output_format.md, "What ParaView shows"). Run with pvbatch (Debian: python3-paraview),
under xvfb-run where there is no display:

    pvbatch check_paraview.py RUN_DIR SAMPLE_DIR PNG

RUN_DIR: a `granshock run` directory of a 2-D scene with friction (run.xmf, run.h5,
fields.xmf, fields.h5, detachment_convergence.csv). SAMPLE_DIR: write_sample_run's directory
(run3d.xmf: a 3-D run). Each .xmf is opened with the reader ParaView picks for it (Xdmf3ReaderS
in ParaView 5.11), then with the other two XDMF readers; the time steps, arrays (names,
components, tuples) and values are compared with the .h5 files read by h5py. Last, one image
(particles as spheres of their radius, velocity arrows, the Mach number field) is rendered
to PNG and checked to be more than one colour. Each failure prints a "FAIL:" line; the last
line says all passed (the ctest looks for it, since pvbatch's exit status is unreliable).
"""
import csv
import os
import sys

import h5py
import numpy as np
from paraview import servermanager
from paraview.simple import (Delete, GetAnimationScene, Glyph, OpenDataFile, Render,
                             SaveScreenshot, Show, XDMFReader, Xdmf3ReaderS, Xdmf3ReaderT,
                             ColorBy, CreateView)
from vtkmodules.util.numpy_support import vtk_to_numpy
from vtkmodules.vtkIOImage import vtkPNGReader

failures = []


def expect(condition, message):
    if not condition:
        failures.append(message)
        print("FAIL:", message, flush=True)


def open_with(reader, path):
    """The reader proxy: 'default' is what the GUI picks (OpenDataFile)."""
    if reader == "default":
        return OpenDataFile(path)
    if reader == "XDMFReader":
        return XDMFReader(FileNames=[path])
    return {"Xdmf3ReaderS": Xdmf3ReaderS, "Xdmf3ReaderT": Xdmf3ReaderT}[reader](FileName=[path])


def leaves_of(data):
    """The grids of a reader's output, however it nests them in blocks and pieces."""
    if data.IsA("vtkMultiBlockDataSet"):
        children = [data.GetBlock(i) for i in range(data.GetNumberOfBlocks())]
    elif data.IsA("vtkMultiPieceDataSet"):
        children = [data.GetPiece(i) for i in range(data.GetNumberOfPieces())]
    else:
        return [data]
    return [leaf for child in children if child is not None for leaf in leaves_of(child)]


def is_obstacle(grid):
    # The obstacle's grid: one polygon (VTK_POLYGON = 7); the particles are vertices and the
    # fields quadrilaterals of a structured grid.
    return (grid.IsA("vtkDataSet") and grid.GetNumberOfCells() == 1 and
            grid.GetCellType(0) == 7)


def dataset_at(proxy, time=None):
    """The reader's grid (the particles, the fields, a table) and the obstacle's grid beside
    it (None where the file has none)."""
    if time is None:
        proxy.UpdatePipeline()
    else:
        proxy.UpdatePipeline(time)
    leaves = leaves_of(servermanager.Fetch(proxy))
    obstacles = [g for g in leaves if is_obstacle(g)]
    others = [g for g in leaves if not is_obstacle(g)]
    expect(len(others) == 1 and len(obstacles) <= 1,
           f"{len(others)} grids and {len(obstacles)} obstacles")
    return (others[0] if others else None), (obstacles[0] if obstacles else None)


def check_obstacle(obstacle, what, run_h5):
    """The obstacle grid: one polygon of the outline's corners around the scene's obstacle."""
    with h5py.File(run_h5, "r") as f:
        resolved = f["scene/resolved"][()]
    resolved = resolved.decode() if isinstance(resolved, bytes) else resolved
    import tomllib
    o = tomllib.loads(resolved).get("obstacle")
    if o is None:
        expect(obstacle is None, f"{what}: an obstacle grid without an obstacle")
        return
    expect(obstacle is not None, f"{what}: no obstacle grid")
    if obstacle is None:
        return
    expect(obstacle.GetNumberOfCells() == 1, f"{what}: obstacle of {obstacle.GetNumberOfCells()} cells")
    points = vtk_to_numpy(obstacle.GetPoints().GetData())
    centre = np.array(o["centre"], dtype=float)
    if o.get("shape", "cylinder") == "cylinder":
        r = np.hypot(points[:, 0] - centre[0], points[:, 1] - centre[1])
        expect(np.allclose(r, o["diameter"] / 2, rtol=1e-12), f"{what}: obstacle points off its circle")
    expect(np.allclose(points[:, :2].mean(axis=0), centre, rtol=0, atol=1e-9),
           f"{what}: obstacle centred at {points[:, :2].mean(axis=0)}, scene {centre}")


def timesteps(proxy):
    values = proxy.TimestepValues
    return [values] if isinstance(values, float) else list(values)


def arrays_of(attributes):
    return {attributes.GetArrayName(i): vtk_to_numpy(attributes.GetArray(i))
            for i in range(attributes.GetNumberOfArrays())}


def check_particles(xmf, expected_arrays, default_reader):
    """run.xmf (or run3d.xmf): every frame with particles, in every XDMF reader."""
    h5_path = xmf[:-len(".xmf")] + ".h5"
    with h5py.File(h5_path, "r") as f:
        all_ = f["particles/all"]
        counts = all_["count/value"][()]
        times = all_["count/time"][()]
        dim = int(all_["box"].attrs["dimension"])
        stored = {name: all_[name + "/value"][()] for name in all_ if name not in ("box", "count")}
        radius_of = f["parameters/species_radius"][()] if "radius" in all_ else None
    frames = [k for k, n in enumerate(counts) if n > 0]
    expect(len(frames) >= 2, f"{xmf}: fewer than two frames with particles")
    for reader in ("default", "Xdmf3ReaderT", "XDMFReader"):
        what = f"{os.path.basename(xmf)} [{reader}]"
        print(f"{what}: opening", flush=True)
        proxy = open_with(reader, xmf)
        name = proxy.GetXMLName()
        if reader == "default":
            expect(name == default_reader, f"{what}: ParaView picks {name}, expected {default_reader}")
        steps = timesteps(proxy)
        expect(np.array_equal(steps, times[frames]), f"{what}: time steps {steps}, run.h5 {times[frames]}")
        for k in frames:
            n = int(counts[k])
            grid, obstacle = dataset_at(proxy, float(times[k]))
            check_obstacle(obstacle, f"{what} frame {k}", h5_path)
            if grid is None:
                continue
            expect(grid.GetNumberOfPoints() == n, f"{what} frame {k}: {grid.GetNumberOfPoints()} points, expected {n}")
            expect(grid.GetNumberOfCells() == n, f"{what} frame {k}: {grid.GetNumberOfCells()} cells, expected {n}")
            points = vtk_to_numpy(grid.GetPoints().GetData())
            expect(np.array_equal(points[:, :dim], stored["position"][k, :n]), f"{what} frame {k}: positions")
            expect(not points[:, dim:].any(), f"{what} frame {k}: z of a 2-D point")
            got = arrays_of(grid.GetPointData())
            expect(sorted(got) == sorted(expected_arrays), f"{what}: arrays {sorted(got)}, expected {sorted(expected_arrays)}")
            for array, components in expected_arrays.items():
                if array not in got:
                    continue
                values = got[array]
                shape = (n, components) if components > 1 else (n,)
                expect(values.shape == shape, f"{what} frame {k}: {array} shape {values.shape}, expected {shape}")
                if values.shape != shape:
                    continue
                source = stored[array][k, :n]
                if components == 3:
                    width = source.shape[1]
                    expect(np.array_equal(values[:, :width], source), f"{what} frame {k}: {array} values")
                    expect(not values[:, width:].any(), f"{what} frame {k}: {array} z is not 0")
                else:
                    expect(np.array_equal(values, source), f"{what} frame {k}: {array} values")
            if radius_of is not None and "radius" in got:
                expect(np.array_equal(got["radius"], radius_of[got["species"]]), f"{what} frame {k}: radius of species")
            vectors = grid.GetPointData().GetVectors()
            expect(vectors is not None and vectors.GetName() == "velocity",
                   f"{what} frame {k}: velocity is not the active vector")
        Delete(proxy)


def check_fields(xmf):
    """fields.xmf: one 2-D grid of cell fields, no time steps."""
    with h5py.File(os.path.join(os.path.dirname(xmf), "fields.h5"), "r") as f:
        stored = {name: f["fields/" + name][()] for name in f["fields"]}
        vectors = {name: f["vectors/" + name][()] for name in f["vectors"]}
    expect("u" in vectors, "fields.h5: no mean velocity vector u")
    for name, values in vectors.items():  # u = (ux, uy, 0), u_s = (ux_s, uy_s, 0)
        suffix = name[1:]
        expect(np.array_equal(values[..., 0], stored["ux" + suffix], equal_nan=True) and
               np.array_equal(values[..., 1], stored["uy" + suffix], equal_nan=True) and
               not values[..., 2].any(), f"fields.h5: /vectors/{name} is not (ux, uy, 0)")
    for reader in ("default", "Xdmf3ReaderT", "XDMFReader"):
        what = f"fields.xmf [{reader}]"
        print(f"{what}: opening", flush=True)
        proxy = open_with(reader, xmf)
        if reader == "default":
            expect(proxy.GetXMLName() == "Xdmf3ReaderS", f"{what}: ParaView picks {proxy.GetXMLName()}")
        expect(timesteps(proxy) == [], f"{what}: time steps {timesteps(proxy)}")
        grid, obstacle = dataset_at(proxy)
        check_obstacle(obstacle, what, os.path.join(os.path.dirname(xmf), "run.h5"))
        if grid is None:
            continue
        got = arrays_of(grid.GetCellData())
        expected = sorted(list(stored) + list(vectors))
        expect(sorted(got) == expected, f"{what}: cell arrays {sorted(got)}, fields.h5 {expected}")
        for name, values in list(stored.items()) + list(vectors.items()):
            if name not in got:
                continue
            shape = (values.shape[0] * values.shape[1],) + values.shape[2:]
            expect(got[name].shape == shape, f"{what}: {name} has shape {got[name].shape}, expected {shape}")
            if got[name].shape == shape:
                expect(np.array_equal(got[name], values.reshape(shape), equal_nan=True), f"{what}: {name} values")
        active = grid.GetCellData().GetVectors()
        expect(active is not None and active.GetName() == "u", f"{what}: u is not the active cell vector")
        Delete(proxy)


def check_csv(path):
    proxy = OpenDataFile(path)
    expect(proxy is not None and proxy.GetXMLName() == "CSVReader", f"{path}: reader")
    table, _ = dataset_at(proxy)
    with open(path, newline="") as f:
        rows = list(csv.reader(f))
    expect(table.GetNumberOfColumns() == len(rows[0]), f"{path}: {table.GetNumberOfColumns()} columns")
    expect(table.GetNumberOfRows() == len(rows) - 1, f"{path}: {table.GetNumberOfRows()} rows")
    Delete(proxy)


def render(run_dir, png):
    """Particles as spheres of their radius coloured by speed, velocity arrows, and Ma."""
    view = CreateView("RenderView")
    view.ViewSize = [480, 640]
    view.OrientationAxesVisibility = 0
    fields = OpenDataFile(os.path.join(run_dir, "fields.xmf"))
    shown = Show(fields, view)
    ColorBy(shown, ("CELLS", "n"))
    particles = OpenDataFile(os.path.join(run_dir, "run.xmf"))
    GetAnimationScene().UpdateAnimationUsingDataTimeSteps()
    view.ViewTime = particles.TimestepValues[-1]
    spheres = Glyph(Input=particles, GlyphType="Sphere")
    spheres.ScaleArray = ["POINTS", "radius"]
    spheres.ScaleFactor = 2.0  # the unit sphere source has diameter 1
    spheres.GlyphMode = "All Points"
    ColorBy(Show(spheres, view), ("POINTS", "velocity", "Magnitude"))
    arrows = Glyph(Input=particles, GlyphType="Arrow")
    arrows.OrientationArray = ["POINTS", "velocity"]
    arrows.ScaleArray = ["POINTS", "velocity"]
    # The fastest particle's arrow four radii long.
    speeds = particles.PointData["velocity"].GetRange(-1)
    largest = particles.PointData["radius"].GetRange()[1]
    arrows.ScaleFactor = 4 * largest / max(speeds[1], 1e-30)
    arrows.GlyphMode = "All Points"
    Show(arrows, view)
    view.ResetCamera()
    Render(view)
    SaveScreenshot(png, view, ImageResolution=[480, 640])
    expect(os.path.getsize(png) > 0, f"{png} is empty")
    image = vtkPNGReader()
    image.SetFileName(png)
    image.Update()
    pixels = vtk_to_numpy(image.GetOutput().GetPointData().GetScalars())
    colours = len(np.unique(pixels.reshape(len(pixels), -1), axis=0))
    print(f"{png}: {colours} colours", flush=True)
    expect(colours > 10, f"{png}: {colours} colours, expected an image")


def main():
    run_dir, sample_dir, png = sys.argv[1:4]
    check_particles(os.path.join(run_dir, "run.xmf"),
                    {"species": 1, "id": 1, "velocity": 3, "radius": 1, "angular_velocity": 1},
                    "Xdmf3ReaderS")
    check_particles(os.path.join(sample_dir, "run3d.xmf"),
                    {"species": 1, "id": 1, "velocity": 3, "radius": 1}, "Xdmf3ReaderS")
    check_fields(os.path.join(run_dir, "fields.xmf"))
    check_csv(os.path.join(run_dir, "detachment_convergence.csv"))
    render(run_dir, png)
    if failures:
        # Not sys.exit: pvbatch 5.11 crashes tearing down a render view after it.
        raise RuntimeError(f"{len(failures)} failures")
    print("ParaView opens run.xmf, run3d.xmf, fields.xmf and the CSV in every reader; image rendered")


if __name__ == "__main__":
    main()
