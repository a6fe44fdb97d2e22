"""An output directory: its series of steps, its CSV files and its checkpoints."""
import os
import re

from .series import Series
from .table import Table

_STEP = re.compile(r"^(?P<base>.+)_(?P<step>\d{6})\.h5$")
_CHECKPOINT = re.compile(r"^(?P<base>.+)_checkpoint_(?P<step>\d{6})\.h5$")


class Run:
    """The output directory of a run (`output.directory`). Series are named by their base
    (`<scene>`, `<scene>_solid`, `<scene>_fluid`); a name that ends one base (`solid`, `fluid`)
    selects it. CSV files are named by their file name, its stem or the part after the scene
    (`probes` for `<scene>_probes.csv`)."""

    def __init__(self, directory):
        self.directory = str(directory)
        if not os.path.isdir(self.directory):
            raise FileNotFoundError(f"{self.directory}: not a directory")
        files = sorted(os.listdir(self.directory))
        self._steps, self.checkpoints = {}, []
        for name in files:
            if _CHECKPOINT.match(name):
                self.checkpoints.append(os.path.join(self.directory, name))
                continue
            m = _STEP.match(name)
            if m:
                self._steps.setdefault(m.group("base"), []).append(os.path.join(self.directory, name))
        self.series_names = sorted(self._steps)
        self.csv_files = [os.path.join(self.directory, n) for n in files if n.endswith(".csv")]
        self._series = {}

    def __repr__(self):
        return f"Run({self.directory!r}, series {self.series_names})"

    def _pick(self, name, choices, what):
        if name is None:
            if len(choices) == 1:
                return choices[0]
            raise KeyError(f"{self.directory}: {len(choices)} {what}s ({', '.join(choices) or 'none'}); name one")
        exact = [c for c in choices if c == name]
        ending = [c for c in choices if c.endswith("_" + name)]
        found = exact or ending
        if len(found) != 1:
            raise KeyError(f"{self.directory}: {what} '{name}' matches {len(found)} of: {', '.join(choices) or 'none'}")
        return found[0]

    def series(self, name=None):
        """The steps of one base name (the only one when name is None)."""
        base = self._pick(name, self.series_names, "series")
        if base not in self._series:
            self._series[base] = Series(base, self._steps[base])
        return self._series[base]

    def csv(self, name):
        """One CSV file as a Table: `probes`, `coupling`, `restart_block_energies` or a file name."""
        stems = [os.path.basename(p)[:-4] for p in self.csv_files]
        stem = self._pick(name[:-4] if name.endswith(".csv") else name, stems, "CSV file")
        return Table(os.path.join(self.directory, stem + ".csv"))

    def probes(self):
        """`<scene>_probes.csv`: step, time, then per probe <name>_x, <name>_y, <name>_ux, ..."""
        return self.csv("probes")
