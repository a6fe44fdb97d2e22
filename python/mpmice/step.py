"""One output step: `<base>_<step:06d>.h5` (docs/output-format.md, "One step")."""
import h5py
import numpy as np

# The run's description in the root attributes: strings, and one-element integer arrays.
_TEXT_ATTRIBUTES = ("program", "version", "command_line", "rank_layout", "host", "started",
                    "scene_file", "scene_hash", "scene_as_understood")
_COUNT_ATTRIBUTES = ("ranks", "launch_ranks")


def _names(group):
    """The datasets of a group, without the `xdmf` companion group (what the index needs)."""
    return sorted(k for k, v in group.items() if isinstance(v, h5py.Dataset))


class Step:
    """One output file. Arrays are read when asked for and returned as numpy arrays:
    grid fields as (nz, ny, nx[, ncomp]) in C order with x fastest, particles as (n[, ncomp])."""

    def __init__(self, path):
        self.path = str(path)
        with h5py.File(self.path, "r") as f:
            a = f.attrs
            self.time = float(a["time"][0])
            self.step = int(a["step"][0])
            self.dim = int(a["dim"][0])
            self.origin = np.array(a["origin"], dtype=float)
            self.spacing = np.array(a["spacing"], dtype=float)
            self.cells = np.array(a["cells"], dtype=int)          # x, y, z
            self.periodic = np.array(a["periodic"], dtype=bool)
            self.nranks = int(a["nranks"][0])
            self.metadata = {k: a[k].decode() for k in _TEXT_ATTRIBUTES if k in a}
            self.metadata.update({k: int(a[k][0]) for k in _COUNT_ATTRIBUTES if k in a})
            grid = f.get("grid")
            self.cell_names = _names(grid["cell"]) if grid is not None and "cell" in grid else []
            self.node_names = _names(grid["node"]) if grid is not None and "node" in grid else []
            parts = f.get("particles")
            self.particle_names = _names(parts) if parts is not None else []
            self.rank_counts = (np.array(parts.attrs["rank_counts"], dtype=int)
                                if parts is not None and "rank_counts" in parts.attrs else np.zeros(0, int))

    def __repr__(self):
        return f"Step({self.path!r}, step={self.step}, time={self.time!r})"

    def _read(self, group, name, names):
        if name not in names:
            raise KeyError(f"{self.path}: no {group} '{name}' (it holds: {', '.join(names) or 'none'})")
        with h5py.File(self.path, "r") as f:
            return f[f"{group}/{name}"][...]

    def cell(self, name):
        """A cell-centred field, shape (nz, ny, nx) or (nz, ny, nx, ncomp)."""
        return self._read("grid/cell", name, self.cell_names)

    def node(self, name):
        """A node-centred field, shape (nz+1, ny+1, nx+1[, ncomp]); unused directions have extent 1."""
        return self._read("grid/node", name, self.node_names)

    def particle(self, name):
        """A particle array, shape (n) or (n, ncomp); rank 0's particles first."""
        return self._read("particles", name, self.particle_names)

    @property
    def particle_count(self):
        return int(self.rank_counts.sum())

    def cell_centres(self, axis):
        """The cell centres along axis 0 (x), 1 (y) or 2 (z): origin + (i + 1/2) * spacing."""
        return self.origin[axis] + (np.arange(self.cells[axis]) + 0.5) * self.spacing[axis]

    def node_coordinates(self, axis):
        """The node coordinates along an axis (one node, at the origin, in unused directions)."""
        n = self.cells[axis] + 1 if axis < self.dim else 1
        return self.origin[axis] + np.arange(n) * self.spacing[axis]
