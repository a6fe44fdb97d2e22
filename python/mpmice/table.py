"""A CSV summary (docs/output-format.md, "CSV summaries"): a header of column names, then rows."""
import numpy as np


def read_csv(path):
    """Reads one CSV file written by a run into a Table."""
    return Table(path)


class Table:
    """The columns of one CSV file as float arrays: `table["time"]`, `table.columns`."""

    def __init__(self, path):
        self.path = str(path)
        with open(self.path) as f:
            lines = [l.rstrip("\n") for l in f if l.strip()]
        if not lines:
            raise ValueError(f"{self.path}: empty (no header line)")
        self.columns = lines[0].split(",")
        rows = []
        for n, line in enumerate(lines[1:], start=2):
            cells = line.split(",")
            if len(cells) != len(self.columns):
                raise ValueError(f"{self.path}:{n}: {len(cells)} values, the header has {len(self.columns)}")
            rows.append([float(c) for c in cells])
        data = np.array(rows, dtype=float).reshape(len(rows), len(self.columns))
        self._data = {c: data[:, i] for i, c in enumerate(self.columns)}

    def __repr__(self):
        return f"Table({self.path!r}, {len(self)} rows, columns {self.columns})"

    def __len__(self):
        return len(next(iter(self._data.values())))

    def __getitem__(self, column):
        if column not in self._data:
            raise KeyError(f"{self.path}: no column '{column}' (columns: {', '.join(self.columns)})")
        return self._data[column]

    def __contains__(self, column):
        return column in self._data

    def group(self, prefix):
        """The columns named `<prefix>_<rest>` as {rest: array}, e.g. one probe's x, y, ux, uy."""
        p = prefix + "_"
        found = {c[len(p):]: self._data[c] for c in self.columns if c.startswith(p)}
        if not found:
            raise KeyError(f"{self.path}: no column starts with '{p}' (columns: {', '.join(self.columns)})")
        return found
