"""The steps of one base name, in step order: a time series of grid fields and particles."""
import numpy as np

from .step import Step


class Series:
    """The output steps `<base>_<step:06d>.h5` of one program of a run (e.g. `<scene>`,
    `<scene>_solid`, `<scene>_fluid`), in step order."""

    def __init__(self, base, paths):
        self.base = base
        self.steps_ = [Step(p) for p in paths]
        self.steps_.sort(key=lambda s: s.step)

    def __repr__(self):
        return f"Series({self.base!r}, {len(self)} steps)"

    def __len__(self):
        return len(self.steps_)

    def __getitem__(self, i):
        return self.steps_[i]

    def __iter__(self):
        return iter(self.steps_)

    @property
    def steps(self):
        """The step numbers, as an integer array."""
        return np.array([s.step for s in self.steps_], dtype=int)

    @property
    def times(self):
        """The simulated times [s], one per step."""
        return np.array([s.time for s in self.steps_], dtype=float)

    def at(self, time=None, step=None):
        """The output step numbered `step`, or the one whose time is nearest `time`."""
        if (time is None) == (step is None):
            raise ValueError("give exactly one of time= and step=")
        if step is not None:
            for s in self.steps_:
                if s.step == step:
                    return s
            raise KeyError(f"{self.base}: no output step {step} (steps: {list(self.steps)})")
        return self.steps_[int(np.argmin(np.abs(self.times - time)))]

    def cell(self, name):
        """A cell field at every step, stacked: (steps, nz, ny, nx[, ncomp])."""
        return np.stack([s.cell(name) for s in self.steps_])

    def node(self, name):
        """A node field at every step, stacked: (steps, nz+1, ny+1, nx+1[, ncomp])."""
        return np.stack([s.node(name) for s in self.steps_])

    def particles(self, name):
        """A particle array at every step: a list (particle counts may change between steps)."""
        return [s.particle(name) for s in self.steps_]

    def track(self, name, particle_id):
        """One particle's array over time, found by its global id (the `id` array): (steps[, ncomp])."""
        rows = []
        for s in self.steps_:
            hits = np.flatnonzero(s.particle("id") == particle_id)
            if hits.size != 1:
                raise KeyError(f"{s.path}: particle id {particle_id} found {hits.size} times")
            rows.append(s.particle(name)[hits[0]])
        return np.array(rows)
