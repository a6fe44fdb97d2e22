"""Opens a run's XDMF index with ParaView's legacy XDMF reader and both Xdmf3 readers (pvpython)
and checks what a user sees: cell arrays on the 2D grid, particle stress components equal to the
HDF5 values (read with h5dump), one vertex per particle, the same block names at every time.

  pvpython check_xdmf.py OUTPUT_DIR/BASE.xmf
"""
import os
import re
import subprocess
import sys

from paraview import servermanager as sm
from paraview.simple import XDMFReader, Xdmf3ReaderS, Xdmf3ReaderT, Delete
from vtkmodules.util.numpy_support import vtk_to_numpy
import numpy as np

xmf = os.path.abspath(sys.argv[1])
outdir = os.path.dirname(xmf)
failures = []


def check(ok, what):
    print(("ok   " if ok else "FAIL ") + what)
    if not ok:
        failures.append(what)


def h5(file, dataset):
    """A dataset as a numpy array, read with h5dump (no h5py needed)."""
    txt = subprocess.run(["h5dump", "-d", dataset, "-m", "%.17g", "-y", "-w", "0", file],
                         check=True, capture_output=True, text=True).stdout
    dims = [int(v) for v in re.search(r"DATASPACE\s+SIMPLE\s*\{\s*\(([^)]*)\)", txt).group(1).split(",")]
    body = txt[txt.index("DATA {") + 6:txt.rindex("}")]
    vals = np.array([float(v) for v in re.findall(r"[-+0-9.eEinfa]+", body) if v.strip()])
    return vals.reshape(dims)


def blocks(obj, path=""):
    """(path of names, dataset) for every leaf; unnamed blocks and pieces as #i."""
    out = []
    if obj is None:
        return out
    if obj.IsA("vtkMultiBlockDataSet"):
        for i in range(obj.GetNumberOfBlocks()):
            meta = obj.GetMetaData(i) if obj.HasMetaData(i) else None
            name = meta.Get(obj.NAME()) if meta is not None and meta.Has(obj.NAME()) else "#%d" % i
            out += blocks(obj.GetBlock(i), path + "/" + name)
    elif obj.IsA("vtkMultiPieceDataSet"):
        for i in range(obj.GetNumberOfPieces()):
            out += blocks(obj.GetPiece(i), path + "/#%d" % i)
    else:
        out.append((path, obj))
    return out


# The steps and their files, from the index itself.
text = open(xmf).read()
mesh_part = text[text.index('<Grid Name="mesh"'):text.index('<Grid Name="particles"')]
steps = re.findall(r'<Time Value="([^"]+)" />.*?Format="HDF">([^:<]+):', mesh_part, re.S)
check(len(steps) >= 2, "the index lists %d steps (at least 2)" % len(steps))
cell_arrays = sorted(set(re.findall(r'<Attribute Name="([^"]+)" AttributeType="[^"]+" Center="Cell">', mesh_part)))
check(len(cell_arrays) > 0, "the mesh has cell arrays: %s" % ", ".join(cell_arrays))

readers = [("legacy XDMF reader", lambda: XDMFReader(FileNames=[xmf])),
           ("Xdmf3ReaderS", lambda: Xdmf3ReaderS(FileName=[xmf])),
           ("Xdmf3ReaderT", lambda: Xdmf3ReaderT(FileName=[xmf]))]
for label, make in readers:
    r = make()
    if label == "legacy XDMF reader":
        r.CellArrayStatus = r.CellArrayStatus.Available
        r.PointArrayStatus = r.PointArrayStatus.Available
    times = list(r.TimestepValues)
    check(len(times) == len(steps), "%s: %d times (the index has %d)" % (label, len(times), len(steps)))
    layout = None
    for (tstr, h5name) in steps:
        t = float(tstr)
        r.UpdatePipeline(t)
        leaves = blocks(sm.Fetch(r))
        names = [p for p, _ in leaves]
        grids = [(p, d) for p, d in leaves if d.IsA("vtkImageData")]
        parts = [(p, d) for p, d in leaves if d.IsA("vtkUnstructuredGrid")]
        where = "%s, t = %s" % (label, tstr)
        check(len(grids) == 1 and len(parts) == 1,
              "%s: one grid block and one particle block (%s)" % (where, names))
        if layout is None:
            layout = names
            if label == "legacy XDMF reader":
                check(names == ["/mesh", "/particles"], "%s: blocks named mesh, particles (%s)" % (where, names))
        check(names == layout, "%s: block names as at the first time (%s vs %s)" % (where, names, layout))
        if len(grids) != 1 or len(parts) != 1:
            continue
        g = grids[0][1]
        h5file = os.path.join(outdir, h5name)
        for a in cell_arrays:
            arr = g.GetCellData().GetArray(a)
            ok = arr is not None
            if ok:
                ref = h5(h5file, "/grid/cell/" + a)
                ncomp = arr.GetNumberOfComponents()
                got = vtk_to_numpy(arr).reshape(-1, ncomp)
                ok = got.shape[0] == g.GetNumberOfCells() and np.array_equal(got.ravel(), ref.ravel())
            check(ok, "%s: cell array %s loaded, equal to the HDF5 values" % (where, a))
        p = parts[0][1]
        pos = h5(h5file, "/particles/position")
        n = pos.shape[0]
        check(p.GetNumberOfPoints() == n and p.GetNumberOfCells() == n,
              "%s: %d particles give %d points and %d vertex cells" % (where, n, p.GetNumberOfPoints(),
                                                                      p.GetNumberOfCells()))
        check(all(p.GetCell(c).GetNumberOfPoints() == 1 for c in range(p.GetNumberOfCells())),
              "%s: every particle cell holds one point" % where)
        stress = p.GetPointData().GetArray("stress")
        check(stress is not None and stress.GetNumberOfComponents() == 9,
              "%s: particle stress has 9 components" % where)
        if stress is None or stress.GetNumberOfComponents() != 9:
            continue
        s9 = vtk_to_numpy(stress).reshape(n, 3, 3)
        s6 = h5(h5file, "/particles/stress")  # xx, yy, zz, xy, yz, xz
        for k, (name, (i, j)) in enumerate(zip(["xx", "yy", "zz", "xy", "yz", "xz"],
                                               [(0, 0), (1, 1), (2, 2), (0, 1), (1, 2), (0, 2)])):
            check(np.array_equal(s9[:, i, j], s6[:, k]) and np.array_equal(s9[:, j, i], s6[:, k]),
                  "%s: stress %s (ParaView components %d and %d) equals HDF5 column %d" %
                  (where, name, 3 * i + j, 3 * j + i, k))
        check(np.array_equal(vtk_to_numpy(p.GetPoints().GetData()), pos), "%s: particle positions" % where)
    Delete(r)

print("%d checks failed" % len(failures) if failures else "all checks passed")
sys.exit(1 if failures else 0)
