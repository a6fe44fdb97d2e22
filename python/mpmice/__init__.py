"""Reading an MPM-ICE run's output (docs/output-format.md) with h5py and numpy.

    import mpmice
    run = mpmice.Run("output/pressurized_cylinder")     # an output directory
    fluid = run.series("fluid")                         # the steps of <scene>_fluid_<step>.h5
    p = fluid.cell("pressure")                          # (steps, nz, ny, nx), one row per step
    tip = run.csv("probes")                             # <scene>_probes.csv as numpy columns

Step: one output file; Series: the steps of one base name in step order; Run: an output
directory (its series, CSV files and checkpoints); Table: one CSV file.
"""
from .step import Step
from .series import Series
from .table import Table, read_csv
from .run import Run

__all__ = ["Run", "Series", "Step", "Table", "read_csv"]
__version__ = "0.1.0"
