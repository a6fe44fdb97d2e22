"""python/mpmice read back against h5dump and the CSV text, on the outputs run_python_reader.sh made
in the current directory: block/ (mpm_solver alone) and cylinder/ (an MPMD coupler run)."""
import csv
import glob
import os
import re
import subprocess
import tempfile
import unittest

import numpy as np

import mpmice


def h5dump_values(path, dataset):
    """The dataset's values as h5dump writes them in binary (little-endian doubles), flat."""
    with tempfile.NamedTemporaryFile(suffix=".bin") as out:
        subprocess.run(["h5dump", "-d", dataset, "-b", "LE", "-o", out.name, path], check=True,
                       stdout=subprocess.DEVNULL)
        return np.fromfile(out.name, dtype="<f8")


def h5dump_attribute(path, name):
    """A root attribute's text as h5dump prints it (doubles with 17 significant digits)."""
    text = subprocess.run(["h5dump", "-m", "%.17g", "-a", name, path], check=True, capture_output=True,
                          text=True).stdout
    body = re.search(r"DATA \{(.*?)\}", text, re.S).group(1)
    return ", ".join(v.strip() for v in re.sub(r"\(\d+\):", "", body).split(","))


def step_files(directory, base):
    return sorted(p for p in glob.glob(os.path.join(directory, base + "_*.h5"))
                  if re.search(r"_\d{6}\.h5$", p) and "_checkpoint_" not in p)


def csv_text(path):
    with open(path) as f:
        rows = list(csv.reader(f))
    return rows[0], rows[1:]


class SolidAlone(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.out = mpmice.Run("block")

    def test_one_series_of_every_step_file(self):
        self.assertEqual(self.out.series_names, ["restart_block"])
        s = self.out.series()
        files = step_files("block", "restart_block")
        self.assertEqual([st.path for st in s], files)
        self.assertEqual(list(s.steps), [int(f[-9:-3]) for f in files])
        self.assertEqual(len(self.out.checkpoints), len(glob.glob("block/*_checkpoint_*.h5")))

    def test_times_and_mesh_equal_the_attributes(self):
        for st in self.out.series():
            self.assertEqual(st.time, float(h5dump_attribute(st.path, "time")))
            self.assertEqual(st.step, int(h5dump_attribute(st.path, "step")))
            spacing = [float(v) for v in h5dump_attribute(st.path, "spacing").split(",")]
            self.assertEqual(list(st.spacing), spacing)
        first = self.out.series()[0]
        self.assertEqual(first.dim, 2)
        self.assertEqual(len(first.cell_centres(0)), first.cells[0])
        self.assertAlmostEqual(first.cell_centres(0)[0], first.origin[0] + 0.5 * first.spacing[0])
        self.assertEqual(len(first.node_coordinates(0)), first.cells[0] + 1)
        self.assertEqual(len(first.node_coordinates(2)), 1)

    def test_node_fields_over_time_equal_h5dump(self):
        s = self.out.series()
        self.assertIn("velocity", s[0].node_names)
        self.assertNotIn("xdmf", s[0].node_names)
        v = s.node("velocity")
        self.assertEqual(v.shape[0], len(s))
        self.assertEqual(v.shape[1:], (1, s[0].cells[1] + 1, s[0].cells[0] + 1, 3))
        for i, st in enumerate(s):
            np.testing.assert_array_equal(v[i].ravel(), h5dump_values(st.path, "/grid/node/velocity"))
        self.assertGreater(np.abs(v[-1]).max(), 0.0)

    def test_particles_equal_h5dump_and_follow_an_id(self):
        s = self.out.series()
        for st in (s[0], s[len(s) // 2], s[-1]):
            for name in ("position", "stress", "mass", "id"):
                np.testing.assert_array_equal(st.particle(name).ravel(), h5dump_values(st.path, "/particles/" + name))
            self.assertEqual(st.particle_count, len(st.particle("mass")))
        ids = s[0].particle("id")
        pid = ids[7]
        track = s.track("position", pid)
        self.assertEqual(track.shape, (len(s), 3))
        for i, st in enumerate(s):
            row = int(np.flatnonzero(st.particle("id") == pid)[0])
            np.testing.assert_array_equal(track[i], st.particle("position")[row])
        self.assertFalse(np.array_equal(track[0], track[-1]))   # the block moves

    def test_probe_and_energy_columns_equal_the_csv_text(self):
        for name in ("probes", "energies"):
            t = self.out.csv(name)
            header, rows = csv_text(t.path)
            self.assertEqual(t.columns, header)
            self.assertEqual(len(t), len(rows))
            for j, c in enumerate(header):
                np.testing.assert_array_equal(t[c], [float(r[j]) for r in rows])
        corner = self.out.probes().group("corner")
        self.assertEqual(sorted(corner), ["ux", "uy", "x", "y"])
        # position - displacement is the start point (to the CSV's 12 digits)
        np.testing.assert_allclose(corner["x"] - corner["ux"], corner["x"][0], rtol=0, atol=1e-10)

    def test_errors_name_the_file_and_the_choices(self):
        st = self.out.series()[0]
        with self.assertRaisesRegex(KeyError, r"restart_block_000000\.h5: no grid/node 'speed' .*velocity"):
            st.node("speed")
        with self.assertRaisesRegex(KeyError, "no column 'speed'"):
            self.out.probes()["speed"]
        with self.assertRaisesRegex(KeyError, "CSV file 'nothing'"):
            self.out.csv("nothing")


class CoupledLaunch(unittest.TestCase):
    @classmethod
    def setUpClass(cls):
        cls.out = mpmice.Run("cylinder")

    def test_solid_and_fluid_series(self):
        self.assertEqual(self.out.series_names, ["restart_cylinder_fluid", "restart_cylinder_solid"])
        with self.assertRaisesRegex(KeyError, "2 seriess|name one"):
            self.out.series()
        fluid, solid = self.out.series("fluid"), self.out.series("solid")
        self.assertEqual([st.path for st in fluid], step_files("cylinder", "restart_cylinder_fluid"))
        np.testing.assert_array_equal(fluid.times, solid.times)
        self.assertEqual(fluid.times[-1], 1.5e-4)
        self.assertEqual(fluid.at(step=int(fluid.steps[2])).path, fluid[2].path)
        self.assertEqual(fluid.at(time=fluid.times[3] * 1.001).path, fluid[3].path)

    def test_cell_fields_over_time_equal_h5dump(self):
        fluid = self.out.series("fluid")
        p = fluid.cell("pressure")
        self.assertEqual(p.shape, (len(fluid), 1, 12, 12))
        u = fluid.cell("air_velocity")
        self.assertEqual(u.shape, (len(fluid), 1, 12, 12, 3))
        for i, st in enumerate(fluid):
            np.testing.assert_array_equal(p[i].ravel(), h5dump_values(st.path, "/grid/cell/pressure"))
            np.testing.assert_array_equal(u[i].ravel(), h5dump_values(st.path, "/grid/cell/air_velocity"))
        self.assertGreater(p[-1, 0, 0, 0], p[0, 0, 0, 0])      # the heated air inside the wall

    def test_solid_particles_equal_h5dump(self):
        solid = self.out.series("solid")
        stress = solid.particles("stress")
        for i, st in enumerate(solid):
            np.testing.assert_array_equal(stress[i].ravel(), h5dump_values(st.path, "/particles/stress"))
            self.assertEqual(stress[i].shape, (st.particle_count, 6))

    def test_metadata_is_the_runs_description(self):
        st = self.out.series("solid")[-1]
        self.assertEqual(st.metadata["program"], "mpm_solver")
        self.assertEqual(st.metadata["launch_ranks"], 2)
        self.assertEqual('"%s"' % st.metadata["scene_hash"], h5dump_attribute(st.path, "scene_hash"))
        self.assertEqual(st.metadata["scene_hash"], self.out.series("fluid")[0].metadata["scene_hash"])

    def test_csv_files_equal_their_text(self):
        for name in ("coupling", "conservation", "probes"):
            t = self.out.csv(name)
            header, rows = csv_text(t.path)
            self.assertEqual(t.columns, header)
            for j, c in enumerate(header):
                np.testing.assert_array_equal(t[c], [float(r[j]) for r in rows])
        steps = self.out.csv("coupling")
        self.assertEqual(list(steps["step"]), list(range(1, len(steps) + 1)))
        self.assertEqual(set(self.out.probes().group("inner")), {"x", "y", "ux", "uy"})
        self.assertEqual(len(self.out.probes()), len(steps) + 1)   # t = 0, then every step


if __name__ == "__main__":
    unittest.main()
