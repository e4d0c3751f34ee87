"""Run by tests/python_package.sh in the venv it installed hertzdash into with pip: the module is
the venv's, needs nothing of the build or source tree, finds its data tables and NumPy, and gives
the program's result for the same run.
Usage: python -I python_package_check.py PROGRAM_JSON
(the JSON of `hertzdash simulate --rod steel --height 0.02 --json` from the build tree)
"""
import json
import os
import sys
import sysconfig
import warnings

import numpy as np

import hertzdash

program = json.load(open(sys.argv[1]))
module = os.path.realpath(hertzdash.__file__)
venv = os.path.realpath(sys.prefix)
site_packages = os.path.realpath(sysconfig.get_paths()["platlib"])
assert sys.prefix != sys.base_prefix, "not run in a venv"
assert os.path.dirname(module) == site_packages, f"{module} is not in the venv's {site_packages}"
data_dir = os.path.realpath(hertzdash.paper_parameters()["data_dir"])
assert data_dir.startswith(venv + os.sep), f"data tables read from {data_dir}, not from the venv"

with warnings.catch_warnings():
    warnings.simplefilter("ignore")  # the paper's steel drop exceeds the yield onset: a UserWarning
    run = hertzdash.simulate(rod="steel", height=0.02)
    trace = hertzdash.trace(rod="steel", height=0.02)
assert run["peak_force_N"] > 0 and run["contact_time_s"] > 0, run
assert 0 < run["e_effective"] < 1, run["e_effective"]
# The effective restitution is the ratio of the speeds (a result that contradicts itself fails).
assert abs(run["rebound_velocity_mps"] / run["impact_velocity_mps"] - run["e_effective"]) < 1e-9, run
for key in ("e_effective", "peak_force_N", "contact_time_s"):
    assert run[key] == program[key], (key, run[key], program[key])
assert isinstance(trace["force_N"], np.ndarray) and trace["force_N"].max() > 0
assert abs(trace["force_N"].max() - run["peak_force_N"]) <= 0.05 * run["peak_force_N"]
print(f"python_package: {module} (NumPy {np.__version__}), data {data_dir}: "
      f"e_effective {run['e_effective']:.6f}, peak force {run['peak_force_N']:.1f} N, as the program")
