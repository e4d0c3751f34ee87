"""The Python module `hertzdash` (python/hertzdash_module.cpp) against the program and
against itself. It shares the program's option table and reports, so its results must
be the program's to the last bit: JSON carries doubles with 17 significant digits and
the trace CSV likewise, both of which read back exactly.

Run by ctest (test `python_module`) with PYTHONPATH=build/python and HERTZDASH_BIN set.
"""
import csv
import json
import math
import os
import re
import subprocess
import sys
import warnings

import numpy as np
import pytest

import hertzdash

BIN = os.environ["HERTZDASH_BIN"]
SOURCE = os.environ["HERTZDASH_SOURCE_DIR"]


def cli(*args):
    r = subprocess.run([BIN, *args], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    return r.stdout


def cli_json(*args):
    return json.loads(cli(*args, "--json"))


@pytest.mark.parametrize("integrator", [i["name"] for i in hertzdash.integrators()])
def test_simulate_is_the_programs_json_for_every_integrator(integrator):
    # Fixed-step rows at their default step would warn about resolution; the dict is the
    # same either way, so the default is kept.
    assert hertzdash.simulate(rod="steel", height=0.02, integrator=integrator) == \
        cli_json("simulate", "--rod", "steel", "--height", "0.02", "--integrator", integrator)


def test_simulate_takes_every_option_as_the_program_does():
    options = dict(rod="duralumin-c", impact_velocity=0.5, ball_E=2.9e9, ball_nu=0.35, rod_nu=0.33,
                   restitution=0.7, no_tension=True, zeta="exact", damping="hongo",
                   integrator="dopri5", rtol=1e-9, atol=1e-13, max_step=1e-4)
    args = []
    for key, value in options.items():
        flag = "--" + key.replace("_", "-")
        args += [flag] if value is True else [flag, repr(value) if isinstance(value, float) else str(value)]
    assert hertzdash.simulate(**options) == cli_json("simulate", *args)


def test_keywords_are_the_programs_options():
    # Every Python keyword is a --option of `simulate` (its help lists them all).
    help_text = cli("simulate", "--help")
    doc = hertzdash.simulate.__doc__
    for line in doc.split("Options")[1].splitlines()[1:]:
        keyword = line.strip().split(":")[0]
        assert "--" + keyword.replace("_", "-") in help_text, keyword


def test_trace_is_the_programs_csv(tmp_path):
    csv = tmp_path / "trace.csv"
    cli("simulate", "--rod", "steel", "--height", "0.02", "--trace", str(csv))
    lines = [line for line in csv.read_text().splitlines() if not line.startswith("#")]
    columns = lines[0].split(",")
    table = np.array([[float(cell) for cell in line.split(",")] for line in lines[1:]])
    trace = hertzdash.trace(rod="steel", height=0.02)
    assert list(trace) == columns
    for k, name in enumerate(columns):
        np.testing.assert_array_equal(trace[name], table[:, k], err_msg=name)


def test_trace_on_a_uniform_grid():
    # The grid interpolates CVODE's accepted steps (h ~ 7e-6 s ~ t_c/180 at the defaults).
    # Reference: RK4 with a 1e-7 s step, on the same grid: its error, ~(h w)^4 with
    # w = pi/t_c ~ 2500 rad/s, is ~4e-15 of the amplitudes. What remains is
    #  - CVODE's global error at its default rtol 1e-8, atol 1e-12 (of X, v0): ~1e-7 of x_max and
    #    ~4e-7 of v0 (it falls with rtol: 2.5e-8 and 3e-8 at rtol 1e-10); the cubic Hermite
    #    interpolation's own part, ~(h w)^4/384 ~ 2e-10, is far below it;
    #  - the force, interpolated linearly: ~(h w)^2/8 ~ 4e-5 of the peak where it is smooth,
    #    up to ~1e-3 on the steps next to onset and separation, where the paper's law's force
    #    grows like t^{3/2} (its second derivative is unbounded).
    # The bounds are these errors with a margin of 2-3.
    grid = 1e-6
    coarse = hertzdash.trace(grid_step=grid, rod="steel", height=0.02, integrator="cvode")
    fine = hertzdash.trace(grid_step=grid, rod="steel", height=0.02, integrator="rk4", dt=1e-7)
    t = coarse["t_s"]
    np.testing.assert_allclose(np.diff(t), grid, rtol=1e-6)
    assert t[0] == hertzdash.trace(rod="steel", height=0.02)["t_s"][0]  # the grid starts at contact onset
    assert abs(len(t) - len(fine["t_s"])) <= 1  # the same contact time, to within a grid step
    n = min(len(t), len(fine["t_s"]))
    assert n > 1000
    x_max, v0, peak = coarse["x_m"].max(), coarse["xdot_mps"][0], coarse["force_N"].max()
    assert np.abs(coarse["x_m"][:n] - fine["x_m"][:n]).max() < 3e-7 * x_max
    assert np.abs(coarse["xdot_mps"][:n] - fine["xdot_mps"][:n]).max() < 1e-6 * v0
    assert np.abs(coarse["force_N"][:n] - fine["force_N"][:n]).max() < 2e-3 * peak


def test_simulate_many_is_simulate_point_by_point():
    # 40 points on 2 threads: chunks of 5, so both threads run impacts.
    heights = np.linspace(0.005, 0.05, 40)
    e = np.linspace(0.5, 1.0, 40)
    many = hertzdash.simulate_many(threads=2, rod="duralumin-a", height=heights, restitution=e, damping="flores",
                                   integrator="gbs8-regularized")
    assert len(many["e_effective"]) == 40
    one_thread = hertzdash.simulate_many(threads=1, rod="duralumin-a", height=heights, restitution=e,
                                         damping="flores", integrator="gbs8-regularized")
    for i, (h, ei) in enumerate(zip(heights, e)):
        s = hertzdash.simulate(rod="duralumin-a", height=float(h), restitution=float(ei), damping="flores",
                               integrator="gbs8-regularized")
        for key, values in many.items():
            # simulate_many() gives each point's warning codes; simulate() the whole warnings.
            expected = [w["code"] for w in s[key]] if key == "warnings" else s[key]
            assert values[i] == expected, (key, i)
            assert one_thread[key][i] == expected, (key, i)


def fields_of(group, report):
    """The names of the result fields (simulation/run/result_fields.hpp) of `group` a front end reports."""
    return [f["name"] for f in hertzdash.result_fields() if f[report] and f["group"] == group]


@pytest.mark.parametrize("options, group", [
    (dict(rod="steel", height=0.02), None),
    (dict(rod="steel", height=0.02, omega_n="self-consistent"), "omega_n_fixed_point"),
    (dict(rod="steel", height=0.02, rod_model="elastic", integrator="rk4"), "elastic_rod"),
])
def test_simulate_returns_the_result_fields_table_in_its_order(options, group):
    # The top-level fields, less the groups the run has not; a group's keys are its fields (a
    # fixed step: the elastic rod's step fields included).
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        r = hertzdash.simulate(**options)
    groups = {f["group"] for f in hertzdash.result_fields() if f["group"]}
    top = [name for name in fields_of("", "json") if name not in groups or name == group]
    assert list(r) == ["schema_version", *top, "inputs", "git_revision"]
    if group:
        assert list(r[group]) == fields_of(group, "json")


def test_simulate_many_returns_the_result_fields_table_in_its_order():
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        r = hertzdash.simulate_many(height=[0.01, 0.02], rod="steel")
    fields = [f for f in hertzdash.result_fields() if f["simulate_many"]]
    assert list(r) == [f["name"] for f in fields]
    for f in fields:
        if f["type"] == "boolean":
            assert r[f["name"]].dtype == np.bool_, f["name"]
        elif f["type"] == "number":
            assert r[f["name"]].dtype == np.float64, f["name"]
        else:
            assert f["name"] == "warnings" and [type(w) for w in r["warnings"]] == [list, list]


def test_simulate_many_broadcasts_scalars_and_length_one_arrays():
    r = hertzdash.simulate_many(height=[0.01, 0.02, 0.03], ball_E=[2.5e9], rod="steel")
    assert all(len(v) == 3 for v in r.values())
    assert r["e_effective"][1] == hertzdash.simulate(height=0.02, ball_E=2.5e9)["e_effective"]


@pytest.mark.parametrize("options, key, message", [
    (dict(mass=-1.0), "mass", "> 0"),
    (dict(restitution=1.5), "restitution", "(0, 1]"),
    (dict(ball_nu=0.6), "ball-nu", "(-1, 0.5)"),
    (dict(height=math.nan), "height", ">= 0"),
    (dict(rod="brass"), "rod", "steel"),
    (dict(damping="no-such-law"), "damping", "hongo"),
    (dict(integrator="rk5"), "integrator", "rk4"),
    (dict(rtol=-1.0), "rtol", "in (0, 1)"),
    (dict(integrator="rk4", rtol=1e-6), "rtol", "given only with {integrator} cvode"),
    (dict(integrator="rk4", dt=0.01), "dt", "at most"),
    (dict(rod_elements=10), "rod-elements", "given only with {rod-model} elastic"),
    (dict(zeta="exact", damping="flores"), "zeta", "given only with {damping} hongo"),
    (dict(rod_model="elastic", rod_elements=2.5), "rod-elements", "an integer in [1, 400]"),
    (dict(rod_model="elastic", cell_damping_ratio=1.0), "cell-damping-ratio", "[0, 1)"),
])
def test_bad_input_names_the_keyword_in_python_and_the_option_on_the_command_line(options, key, message):
    # One refusal {key, value, range}, spelled by each front end: ball_nu in Python, --ball-nu
    # on the command line, also where the range names another option.
    with pytest.raises(ValueError) as error:
        hertzdash.simulate(**options)
    text = str(error.value)
    keys = ("integrator", "rod-model", "damping")
    python = {k: k.replace("-", "_") for k in keys}
    assert text.startswith(f"invalid {key.replace('-', '_')} = "), text
    assert message.format(**python) in text, text
    assert "--" not in text, text
    args = []
    for k, value in options.items():
        args += ["--" + k.replace("_", "-"), str(value)]
    r = subprocess.run([BIN, "simulate", *args], capture_output=True, text=True)
    assert r.returncode == 2
    assert r.stderr.startswith(f"hertzdash: invalid --{key} = "), r.stderr
    assert message.format(**{k: "--" + k for k in keys}) in r.stderr, r.stderr


def test_wrong_keywords_and_types_raise_type_error():
    with pytest.raises(TypeError, match="unexpected keyword argument 'heigth'"):
        hertzdash.simulate(heigth=0.02)
    with pytest.raises(TypeError, match="height: expected a number"):
        hertzdash.simulate(height="0.02")
    with pytest.raises(TypeError, match="no_tension: expected True or False"):
        hertzdash.simulate(no_tension=1)
    with pytest.raises(ValueError, match="grid_step"):
        hertzdash.trace(grid_step=0.0)
    with pytest.raises(ValueError, match="length 3"):
        hertzdash.simulate_many(height=[0.01, 0.02, 0.03], restitution=[0.7, 0.8])
    with pytest.raises(ValueError, match="single value"):
        hertzdash.simulate_many(rtol=[1e-8, 1e-9])
    with pytest.raises(TypeError, match="height: expected numbers"):
        hertzdash.simulate_many(height=["0.01", "0.02"])
    with pytest.raises(ValueError, match=r"point 1: invalid mass"):
        hertzdash.simulate_many(mass=[0.5, -0.5, 0.7])
    with pytest.raises(ValueError, match="invalid height"):
        hertzdash.simulate(height=10**400)
    with pytest.raises(ValueError, match="grid_step"):
        hertzdash.trace(grid_step=math.inf)


def test_none_keeps_the_papers_value():
    assert hertzdash.simulate(omega_n=None, mass=None) == hertzdash.simulate()


def test_a_fall_back_is_a_warning():
    # The integrator table: with the tension clamp gbs8-regularized runs dopri5 (the CLI's note).
    with pytest.warns(UserWarning, match="integrator gbs8-regularized fell back to dopri5"):
        r = hertzdash.simulate(integrator="gbs8-regularized", no_tension=True)
    assert r["integrator_used"] == "dopri5"


def test_result_checks_are_the_programs():
    # Euler at dt = 1e-6 s takes 1211 steps per undamped Hertz contact time of the 20 mm drop,
    # below the 10240 the convergence study needs (under_resolved); at 1e-4 s, 12 steps, Euler's
    # energy gain makes e_effective about 1.3 for a law that dissipates: an error (RuntimeError,
    # the program's exit 1), never a number.
    clean = dict(ball_yield_stress=float("inf"))
    for function, command in [(hertzdash.restitution, "restitution"), (hertzdash.bounce, "bounce")]:
        with pytest.warns(UserWarning, match="the fixed step resolved the contact") as record:
            r = function(integrator="euler", dt=1e-6, **clean)
        # The dict is the program's JSON (options as --key); the UserWarnings name keywords.
        assert [as_keywords(w["message"]) for w in r["warnings"]] == [str(w.message) for w in record]
        assert r == cli_json(command, "--integrator", "euler", "--dt", "1e-6", "--ball-yield-stress", "inf")
        # The error names the keyword to change (dt), as the program names --dt.
        with pytest.raises(RuntimeError, match="the run is under-resolved: e_effective = 1.2") as error:
            function(integrator="euler", dt=1e-4)
        assert "a smaller dt (it is 0.0001 s" in str(error.value) and "--dt" not in str(error.value)
    # rtol above 1e-4: loose_tolerance; at 1e-4: nothing.
    with pytest.warns(UserWarning, match="rtol 0.5 is above 0.0001"):
        assert [w["code"] for w in hertzdash.simulate(rtol=0.5, **clean)["warnings"]] == ["loose_tolerance"]
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        assert hertzdash.simulate(rtol=1e-4, **clean)["warnings"] == []
    # simulate_many: each point's codes, one UserWarning per code with its count (the 20 mm drop
    # exceeds the yield onset at the assumed yield stress, not without a yield check).
    with pytest.warns(UserWarning, match="1 of 2 points: yield_onset"):
        many = hertzdash.simulate_many(ball_yield_stress=[float("inf"), 7e7])
    assert many["warnings"] == [[], ["yield_onset"]]


def test_restitution_and_calibration_are_the_programs():
    assert hertzdash.restitution(damping="hunt-crossley", impact_velocity=1.0) == \
        cli_json("restitution", "--damping", "hunt-crossley", "--impact-velocity", "1")
    cal = hertzdash.calibrate_restitution(0.795, damping="hongo")
    assert cal == cli_json("restitution", "--damping", "hongo", "--target-restitution", "0.795")
    # Calibrated: the law run at the input found returns the target (Brent to 1e-10 in e_input,
    # e_effective accurate to ~1e-7 at the default tolerances).
    assert abs(hertzdash.restitution(damping="hongo", restitution=cal["e_input"])["e_effective"] - 0.795) < 1e-6


def test_laws_integrators_and_version():
    assert hertzdash.laws() == cli_json("models")
    names = [i["name"] for i in hertzdash.integrators()]
    assert "cvode" in names and "gbs8-regularized" in names
    assert cli("--version").strip() == f"hertzdash {hertzdash.__version__} (git {hertzdash.git_revision})"
    # The schema version is the one docs/json-output.md documents.
    title = open(os.path.join(SOURCE, "docs", "json-output.md")).readline()
    assert title.strip() == f"# JSON output (schema version {hertzdash.schema_version})"


def test_paper_parameters_are_the_tables():
    p = hertzdash.paper_parameters()
    steel = next(r for r in p["rods"] if r["name"] == "steel")
    assert steel["mass_kg"] == 0.778 and steel["restitution"] == 0.795  # Tables 1 and 2
    assert p["ball"]["E_min_Pa"] == 1.2e9 and p["ball"]["E_max_Pa"] == 2.9e9  # Table 3
    # The uncertain inputs are the rows of data/assumptions.csv that are not fixed, with their
    # distributions: nylon's E uniform over Table 3's range, as the CSV says.
    with open(os.path.join(p["data_dir"], "assumptions.csv")) as f:
        rows = list(csv.DictReader(line for line in f if not line.startswith("#")))
    varied = [r for r in rows if r["distribution"] != "fixed"]
    inputs = p["uncertain_inputs"]
    assert [u["parameter"] for u in inputs] == [r["parameter"] for r in varied]
    for u, r in zip(inputs, varied):
        assert u["distribution"] == r["distribution"] and u["value"] == float(r["value"]), u["parameter"]
        if r["distribution"] == "uniform":
            assert (u["lower"], u["upper"]) == (float(r["lower"]), float(r["upper"]))
        elif r["distribution"] == "normal":
            assert (u["mean"], u["sd"]) == (float(r["location"]), float(r["scale"]))
        else:
            assert math.isclose(u["median"], float(r["location"]), rel_tol=1e-15) and u["log_sd"] == float(r["scale"])
        assert u["reason"] == r["distribution_reason"]
    nylon_E = next(u for u in inputs if u["parameter"] == "nylon_E_Pa")
    assert nylon_E["distribution"] == "uniform" and (nylon_E["lower"], nylon_E["upper"]) == (p["ball"]["E_min_Pa"], p["ball"]["E_max_Pa"])


def test_the_fig5_example_computes_fig5a():
    # The example's curves (no plotting: matplotlib is optional): the force on a 1 us grid
    # reaches the peak force of simulate() (located as an event) to within the linear
    # interpolation of the force between CVODE's steps, (h w)^2/8 with h ~ 7e-6 s and
    # w = pi/t_c ~ 2500-3000 rad/s: ~4e-5 (the grid's own (w dt)^2/2 ~ 3e-6 is smaller); and a
    # stiffer nylon gives a higher peak (Hertz: P_max ~ K^{2/5} with K ~ E*).
    sys.path.insert(0, os.path.join(SOURCE, "examples"))
    try:
        import fig5_force
    finally:
        sys.path.pop(0)
    curves = fig5_force.curves()
    peaks = {}
    for label, (E, t) in curves.items():
        peak = hertzdash.simulate(rod="steel", height=0.02, ball_E=E)["peak_force_N"]
        assert abs(t["force_N"].max() - peak) < 1e-4 * peak, label
        peaks[E] = peak
    assert [peaks[E] for E in sorted(peaks)] == sorted(peaks.values())
    r = subprocess.run([sys.executable, os.path.join(SOURCE, "examples", "fig5_force.py")], capture_output=True,
                       text=True)
    assert r.returncode == 0, r.stderr
    assert len(r.stdout.splitlines()) == 3


def test_readme_python_examples_print_what_the_readme_shows():
    # Every ```console block of the README that starts with "$ PYTHONPATH=build/python python3 -c"
    # runs (with this interpreter and the build's module) and prints exactly what follows it,
    # stderr (the warnings, which Python prints as they are raised) before stdout.
    prompt = "$ PYTHONPATH=build/python python3 -c "
    lines = open(os.path.join(SOURCE, "README.md")).read().splitlines()
    examples = 0
    for i, line in enumerate(lines):
        if line != "```console" or not lines[i + 1].startswith(prompt):
            continue
        code = lines[i + 1][len(prompt):].strip()
        assert code[0] == code[-1] == '"', code
        expected = []
        for out in lines[i + 2:]:
            if out == "```":
                break
            expected.append(out)
        r = subprocess.run([sys.executable, "-c", code[1:-1]], capture_output=True, text=True)
        assert r.returncode == 0, r.stderr
        assert (r.stderr + r.stdout).splitlines() == expected, code
        examples += 1
    assert examples >= 1


def test_the_elastic_rod_is_the_programs():
    # --rod-model elastic through the same option table: the same summary, energy account and
    # instruments' channels, bit for bit.
    options = dict(rod="duralumin-c", height=0.05, rod_model="elastic", rod_elements=12, cell_stiffness=2e9)
    args = ["--rod", "duralumin-c", "--height", "0.05", "--rod-model", "elastic", "--rod-elements", "12",
            "--cell-stiffness", "2e9"]
    r = hertzdash.simulate(**options)
    expected = cli_json("simulate", *args)
    expected.pop("git_revision")
    r.pop("git_revision")
    assert r == expected
    assert abs(r["elastic_rod"]["energy_balance_error_J"]) < 1e-7 * r["elastic_rod"]["energy_in_J"]
    # The accelerometer's face is read into a trace only; simulate() records none and refuses it.
    trace = hertzdash.trace(**options, accelerometer="bottom")
    assert {"contact_force_N", "rod_accel_mps2"} <= set(trace)
    with pytest.raises(ValueError, match="invalid accelerometer = bottom: must be given only where a trace"):
        hertzdash.simulate(**options, accelerometer="bottom")
    # force_N is what the load cell reads, apart from the contact force by the hemisphere's inertia.
    assert np.abs(trace["force_N"] - trace["contact_force_N"]).max() > 1e-3 * trace["force_N"].max()


def test_bounce_is_the_programs():
    # The same option table and the same report as `hertzdash bounce --json`: onset times,
    # the interval ratios the paper measured and the velocity ratios, to the last bit.
    r = hertzdash.bounce(rod="steel", height=0.02, bounces=5)
    expected = cli_json("bounce", "--rod", "steel", "--height", "0.02", "--bounces", "5")
    for key in ("onset_times_s", "e_from_intervals", "e_velocity_ratio"):
        assert r[key] == expected[key], key
    assert len(r["onset_times_s"]) == 5 and len(r["e_from_intervals"]) == 3
    assert r == expected
    # Calibrated against the first interval ratio, as --target-interval-restitution.
    cal = hertzdash.bounce(target_interval_restitution=0.795, bounces=3)
    assert cal == cli_json("bounce", "--target-interval-restitution", "0.795", "--bounces", "3")
    assert cal["interval_calibration"]["e_target_from_intervals"] == 0.795


def as_keywords(text):
    """The program's text with each option (--key) written as Python's keyword (key with '_')."""
    return re.sub(r"--([A-Za-z][A-Za-z0-9-]*)", lambda m: m.group(1).replace("-", "_"), text)


def assert_same_refusal(stderr, python_text, key):
    """The program refused with the message Python raised, each key spelled as an option (--key)
    where Python spells it as a keyword (key with '_')."""
    assert python_text.startswith(f"invalid {key.replace('-', '_')} = "), python_text
    assert stderr.startswith(f"hertzdash: invalid --{key} = "), stderr
    assert as_keywords(stderr) == "hertzdash: " + python_text + "\n", stderr


@pytest.mark.parametrize("arguments, key", [
    (dict(bounces=0), "bounces"),
    (dict(min_rebound_velocity=-1.0), "min-rebound-velocity"),
    (dict(target_interval_restitution=1.5), "target-interval-restitution"),
    (dict(gravity=0.0), "gravity"),
])
def test_bad_bounce_input_raises_the_programs_message(arguments, key):
    with pytest.raises(ValueError) as error:
        hertzdash.bounce(**arguments)
    args = []
    for keyword, value in arguments.items():
        args += ["--" + keyword.replace("_", "-"), str(value)]
    r = subprocess.run([BIN, "bounce", *args], capture_output=True, text=True)
    assert r.returncode == 2
    assert_same_refusal(r.stderr, str(error.value), key)


def test_a_peak_pressure_beyond_yield_is_a_warning():
    # The paper's steel drop from 20 mm presses the nylon beyond 1.60 Y at the assumed yield
    # stress (the program's stderr warning); with the check off (Y = inf) nothing is said.
    with pytest.warns(UserWarning, match="onset of yield") as record:
        r = hertzdash.simulate()
    message = next(str(w.message) for w in record if "onset of yield" in str(w.message))
    stderr = subprocess.run([BIN, "simulate"], capture_output=True, text=True).stderr
    assert "hertzdash: warning: " + message + "\n" in as_keywords(stderr)
    assert r["exceeds_yield_onset"] is True
    assert r["peak_contact_pressure_Pa"] > r["yield_onset_pressure_Pa"]
    with warnings.catch_warnings(record=True) as caught:
        warnings.simplefilter("always")
        r = hertzdash.simulate(ball_yield_stress=float("inf"))
    assert not [w for w in caught if "yield" in str(w.message)]
    assert r["exceeds_yield_onset"] is False and r["yield_onset_pressure_Pa"] is None


def test_a_deformation_not_small_against_the_ball_is_a_warning():
    # The steel rod from 0.3 m deforms the 12.7 mm ball by 0.71 mm (x/R = 0.056): the sphere
    # departs from Hertz's paraboloid by x/(4R) = 1.4 % > 1 % at the contact's edge. The warning
    # is the program's stderr line and an entry of the result's "warnings".
    with pytest.warns(UserWarning, match="maximum deformation") as record:
        r = hertzdash.simulate(height=0.3, ball_yield_stress=float("inf"))
    message = next(str(w.message) for w in record if "maximum deformation" in str(w.message))
    assert r["exceeds_small_deformation"] is True
    assert [w["message"] for w in r["warnings"] if w["code"] == "large_deformation"] == [message]
    stderr = subprocess.run([BIN, "simulate", "--height", "0.3", "--ball-yield-stress", "inf"],
                            capture_output=True, text=True).stderr
    assert stderr == "hertzdash: warning: " + message + "\n"


def test_virtual_measurement_and_fit_are_the_programs(tmp_path):
    # virtual_measurement() writes the file `simulate --trace-format measured` writes, byte for
    # byte, and fit() returns `fit --json`; the recovered E and e lie within 2 sigma of the truth
    # (the C++ tests cover the statistics).
    py_file, cli_file = tmp_path / "py.csv", tmp_path / "cli.csv"
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        hertzdash.virtual_measurement(str(py_file), noise=0.01, seed=7, ball_E=1.7e9, restitution=0.8,
                                      integrator="rk4", dt=2e-7)
    cli("simulate", "--trace", str(cli_file), "--trace-format", "measured", "--noise", "0.01", "--seed", "7",
        "--ball-E", "1.7e9", "--restitution", "0.8", "--integrator", "rk4", "--dt", "2e-7")
    assert py_file.read_bytes() == cli_file.read_bytes()
    with pytest.warns(UserWarning, match="synthetic: true"):
        r = hertzdash.fit(str(py_file))
    assert r == cli_json("fit", "--trace", str(py_file))
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        profiled = hertzdash.fit(str(py_file), fit="restitution", profile_intervals=True)
    assert profiled == cli_json("fit", "--trace", str(py_file), "--fit", "restitution", "--profile-intervals")
    assert "profile_interval" in profiled["fits"][0]["parameters"][0]
    E, e = r["fits"][0]["parameters"][:2]
    assert abs(E["estimate"] - 1.7e9) < 2 * E["standard_error"]
    assert abs(e["estimate"] - 0.8) < 2 * e["standard_error"]


def test_fit_refuses_solver_options_and_bad_lists(tmp_path):
    trace = tmp_path / "t.csv"
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        hertzdash.virtual_measurement(str(trace))
    with pytest.raises(TypeError, match="solver option 'rtol'"):
        hertzdash.fit(str(trace), rtol=1e-9)
    with pytest.raises(ValueError, match="invalid fit = "):
        hertzdash.fit(str(trace), fit="ball-colour")
    # curves= naming the trace, also through a link, would replace it (issue 31): refused, the trace kept.
    before = trace.read_bytes()
    link = tmp_path / "link.csv"
    link.symlink_to(trace)
    for curves in (trace, link):
        with pytest.raises(ValueError, match=r"invalid curves = .*: must be another file than trace .*the same file"):
            hertzdash.fit(str(trace), curves=str(curves))
    assert trace.read_bytes() == before


def synthetic_restitution_table(path):
    # SYNTHETIC: Kuwabara-Kono's e at A = 7.7e-5 s (`restitution`, CVODE) at six speeds, with a
    # fixed scatter of +-0.004 added, labelled synthetic: a small table the fit needs ~1 s for.
    lines = ["impact_speed_m_per_s,e", "# source: SYNTHETIC, tests/python/test_python_module.py",
             "# synthetic: true"]
    for i, v in enumerate((0.2, 0.4, 0.6, 0.8, 1.0, 1.2)):
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            e = hertzdash.restitution(damping="kuwabara-kono", viscous_time_constant=7.7e-5,
                                      impact_velocity=v, rtol=1e-12)["e_effective"]
        lines.append(f"{v},{e + (0.004 if i % 2 else -0.004)!r}")
    path.write_text("\n".join(lines) + "\n")
    return path


def test_fit_restitution_table_is_the_programs(tmp_path):
    # fit_restitution_table() returns `fit --restitution-table --json`, key for key, with the
    # keywords compare_laws, cross_validate and profile_intervals as the program's flags.
    table = str(synthetic_restitution_table(tmp_path / "kk.csv"))
    with pytest.warns(UserWarning, match="synthetic: true"):
        r = hertzdash.fit_restitution_table(table, damping="kuwabara-kono", cross_validate=True,
                                            profile_intervals=True)
    assert r == cli_json("fit", "--restitution-table", table, "--damping", "kuwabara-kono", "--cross-validate",
                         "--profile-intervals")
    A = r["fits"][0]["parameters"][0]
    assert A["name"] == "viscous-time-constant"
    assert A["profile_interval"][0] < A["estimate"] < A["profile_interval"][1]
    assert abs(A["estimate"] - 7.7e-5) < 3 * A["standard_error"]
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        ranked = hertzdash.fit_restitution_table(table, compare_laws=True)
    assert ranked == cli_json("fit", "--restitution-table", table, "--compare-laws")
    assert ranked["fits"][0]["law"] == "kuwabara-kono"
    with pytest.raises(TypeError, match="solver option 'rtol'"):
        hertzdash.fit_restitution_table(table, rtol=1e-9)
    with pytest.raises(ValueError, match="impact_velocity"):
        hertzdash.fit_restitution_table(table, impact_velocity=0.5)


LIGHT_BALL = dict(mass=2.7e-3, ball_radius=0.02, ball_E=2.4e9, ball_nu=0.35, ball_yield_stress=math.inf,
                  rod_E=200e9, rod_nu=0.3, damping="kelvin-voigt")


def synthetic_bounce_recording(path):
    # SYNTHETIC: the onset times of bounce() for a 2.7 g ball in air (kelvin-voigt, e = 0.9), two
    # drops on clocks of their own, a fixed jitter of +-1e-4 s, and one echo 3 ms after drop b's
    # third impact (row index 3), labelled synthetic.
    lines = ["drop,impact_time_s", "# source: SYNTHETIC, tests/python/test_python_module.py", "# synthetic: true"]
    for label, v0, clock in (("a", 2.0, 5.0), ("b", 2.5, -1.0)):
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")
            t = hertzdash.bounce(bounces=7, impact_velocity=v0, restitution=0.9, air_density=1.204, rtol=1e-12,
                                 **LIGHT_BALL)["onset_times_s"]
        times = [clock + x + (1e-4 if i % 2 else -1e-4) for i, x in enumerate(t)]
        if label == "b":
            times.insert(3, times[2] + 0.003)
        lines += [f"{label},{x!r}" for x in times]
    path.write_text("\n".join(lines) + "\n")
    return path


def test_fit_bounce_times_is_the_programs(tmp_path):
    # fit_bounce_times() returns `fit --bounce-times --json`, key for key; the echo is flagged by
    # drop and index and left out, and the fit with the air it was made in recovers e = 0.9.
    recording = str(synthetic_bounce_recording(tmp_path / "light.csv"))
    with pytest.warns(UserWarning, match="doubled"):
        r = hertzdash.fit_bounce_times(recording, air_density=1.204, **LIGHT_BALL)
    args = [f"--{k.replace('_', '-')}={v}" for k, v in LIGHT_BALL.items()]
    assert r == cli_json("fit", "--bounce-times", recording, "--air-density=1.204", *args)
    assert [(f["drop"], f["index"], f["kind"]) for f in r["flagged"]] == [("b", 3, "doubled")]
    e = r["fits"][0]["parameters"][0]
    assert e["name"] == "restitution"
    assert abs(e["estimate"] - 0.9) < 3 * e["standard_error"]
    with pytest.raises(TypeError, match="solver option 'rtol'"):
        hertzdash.fit_bounce_times(recording, rtol=1e-9)
    # The physical e first, the verdict, and curves= writing e per bounce as the program does
    # (issue 46); the program's --figure is its own (gnuplot), not a keyword.
    assert r["e_effective"] == r["fits"][0]["e_effective"]
    assert r["verdict"] and r["default_body"] is None
    curves = tmp_path / "bounces.csv"
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        hertzdash.fit_bounce_times(recording, air_density=1.204, curves=str(curves), timing_sd=2e-4, **LIGHT_BALL)
    columns = curves.read_text().splitlines()[0].split(",")
    assert columns[:2] == ["drop", "impact_number"] and "e_measured" in columns
    with pytest.raises(TypeError):
        hertzdash.fit_bounce_times(recording, figure=str(tmp_path / "e.png"))


@pytest.fixture(scope="module")
def measured_trace(tmp_path_factory):
    path = tmp_path_factory.mktemp("measured") / "trace.csv"
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        hertzdash.virtual_measurement(str(path))
    return path


# The Python rows of the bad-input matrix (issue 19): every function that refuses input, each
# with the command line that does the same, the key refused and its valid range. OUT marks the
# output file's place in both.
OUT = object()
BAD_INPUT = [
    ("simulate", [], dict(ball_yield_stress=0.0), ["simulate"], "ball-yield-stress", "> 0 or inf"),
    ("trace", [], dict(mass=-1.0), ["simulate", "--trace", OUT], "mass", "> 0"),
    ("restitution", [], dict(restitution=1.5), ["restitution"], "restitution", "in (0, 1]"),
    ("calibrate_restitution", [1.5], {}, ["restitution", "--target-restitution", "1.5"], "target-restitution",
     "in (0, 1]"),
    ("bounce", [], dict(bounces=2.5), ["bounce"], "bounces", "an integer in [1, 1000]"),
    ("bounce", [], dict(min_rebound_velocity=math.nan), ["bounce"], "min-rebound-velocity", ">= 0"),
    ("virtual_measurement", [OUT], dict(sample_rate=0.0), ["simulate", "--trace", OUT, "--trace-format", "measured"],
     "sample-rate", "> 0"),
    ("virtual_measurement", [OUT], dict(noise=2.0), ["simulate", "--trace", OUT, "--trace-format", "measured"],
     "noise", "in [0, 1]"),
    ("virtual_measurement", [OUT], dict(anti_alias=-1.0), ["simulate", "--trace", OUT, "--trace-format", "measured"],
     "anti-alias", "0 (no filter) or a cut-off in (0, 500000] Hz"),
    ("virtual_measurement", [OUT], dict(channels="force_N,colour"),
     ["simulate", "--trace", OUT, "--trace-format", "measured"], "channels", "distinct channels from: force_N"),
    ("virtual_measurement", [OUT], dict(mass=math.nan), ["simulate", "--trace", OUT, "--trace-format", "measured"],
     "mass", "a finite number > 0 (kg)"),
    ("fit", [], dict(curves=OUT, resample=-1.0), ["fit", "--curves", OUT], "resample", "> 0"),
    ("fit", [], dict(curves=OUT, fit="ball-E:1e9:0x10"), ["fit", "--curves", OUT], "fit",
     "NAME:LOWER:UPPER with two decimal numbers"),
    ("fit", [], dict(curves=OUT, mass=-1.0), ["fit", "--curves", OUT], "mass", "a finite number > 0 (kg)"),
    ("fit", [], dict(curves=OUT, channels="colour"), ["fit", "--curves", OUT], "channels", "distinct channels"),
]


@pytest.mark.parametrize("function, args, keywords, command, option, valid", BAD_INPUT,
                         ids=[f"{row[0]}-{row[4]}" for row in BAD_INPUT])
def test_each_refusal_is_a_value_error_naming_the_option_and_range_with_no_file(
        tmp_path, measured_trace, function, args, keywords, command, option, valid):
    out = tmp_path / "out.csv"
    place = lambda v: str(out) if v is OUT else v  # noqa: E731
    args = [place(a) for a in args] + ([str(measured_trace)] if function == "fit" else [])
    keywords = {k: place(v) for k, v in keywords.items()}
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        with pytest.raises(ValueError) as error:
            getattr(hertzdash, function)(*args, **keywords)
    text = str(error.value)
    assert text.startswith(f"invalid {option.replace('-', '_')} = ") and valid in text, text
    assert not out.exists()
    # The program refuses the same input with the same message, and writes no file either.
    line = [place(c) for c in command] + (["--trace", str(measured_trace)] if function == "fit" else [])
    for key, value in keywords.items():
        if key not in ("curves",):
            line += ["--" + key.replace("_", "-"), str(value)]
    r = subprocess.run([BIN, *line], capture_output=True, text=True)
    assert r.returncode == 2, r.stderr
    assert_same_refusal(r.stderr, text, option)
    assert r.stdout == ""
    assert not out.exists()


def test_a_bad_data_table_is_a_value_error_naming_file_line_and_column(tmp_path):
    # The tables are read once per process: a fresh interpreter reads a copy with a second steel row.
    data = tmp_path / "data"
    data.mkdir()
    for f in os.listdir(os.path.join(SOURCE, "data")):
        if f.endswith(".csv"):
            with open(os.path.join(SOURCE, "data", f), "rb") as src:
                (data / f).write_bytes(src.read())
    with open(data / "table1_dimensions.csv", "a") as t:
        t.write("steel,0.0250,0.200,0.5,a second row\n")
    env = dict(os.environ, HERTZDASH_DATA_DIR=str(data))
    r = subprocess.run([sys.executable, "-c", "import hertzdash; hertzdash.simulate()"], capture_output=True,
                       text=True, env=env)
    assert r.returncode != 0
    expected = f"ValueError: bad data file: {data}/table1_dimensions.csv:9:1: column 'body': 'steel' again"
    assert expected in r.stderr, r.stderr


def test_simulate_many_stops_at_ctrl_c():
    # Issue 31: simulate_many ignored Ctrl-C until all its work was done (17 s for 60,000 CVODE
    # points), as Python handles a signal only between its own bytecodes. 200,000 points on one
    # thread take about a minute; SIGINT two seconds in must end the call with KeyboardInterrupt
    # well before (the 30 s timeout fails the test where it would not; the child is killed then).
    import signal
    import time
    code = ("import numpy as np, hertzdash\n"
            "print('running', flush=True)\n"
            "hertzdash.simulate_many(threads=1, height=np.linspace(0.01, 0.05, 200000))\n"
            "print('finished', flush=True)\n")
    p = subprocess.Popen([sys.executable, "-c", code], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    assert p.stdout.readline().strip() == "running"
    time.sleep(2.0)  # past the points' validation, into the runs
    p.send_signal(signal.SIGINT)
    try:
        out, err = p.communicate(timeout=30)
    finally:
        p.kill()
    assert "KeyboardInterrupt" in err
    assert "finished" not in out
    assert p.returncode != 0


@pytest.mark.parametrize("kind", ["fit_bounce_times", "fit_restitution_table"])
def test_fits_stop_at_ctrl_c(kind, tmp_path):
    # Issue 45: Ctrl-C stops a fit as it stops simulate_many. Each fit below runs for about half a
    # minute (a SYNTHETIC recording of 60 drops, or a table of 250 distinct speeds, cross-validated
    # drop by drop, speed by speed); SIGINT three seconds in must end it with KeyboardInterrupt at
    # its next model evaluation: a cross-validation fold's evaluations take milliseconds, and the
    # child's own exit well under a second more. The bound below (5 s) leaves room for a loaded
    # machine; a fit that ignored the signal would run on for half a minute.
    import signal
    import time
    data = tmp_path / "data.csv"
    if kind == "fit_bounce_times":
        lines = ["drop,impact_time_s", "# source: SYNTHETIC, tests/python/test_python_module.py", "# synthetic: true"]
        with warnings.catch_warnings():
            warnings.simplefilter("ignore")  # the paper's rod on nylon: yield and large-deformation notes
            onsets = [hertzdash.bounce(bounces=7, height=h)["onset_times_s"] for h in (0.2, 0.3, 0.4)]
        for d in range(60):
            lines += [f"d{d},{10.0 * d + x + (1e-5 if i % 2 else -1e-5)!r}" for i, x in enumerate(onsets[d % 3])]
    else:
        lines = ["impact_speed_m_per_s,e,e_sd", "# source: SYNTHETIC, tests/python/test_python_module.py"]
        lines += [f"{0.2 + 0.01 * i!r},{0.8 - 0.03 * (0.2 + 0.01 * i) + (0.01 if i % 2 else -0.01)!r},0.01"
                  for i in range(250)]
    data.write_text("\n".join(lines) + "\n")
    code = ("import warnings, hertzdash\n"
            "warnings.simplefilter('ignore')\n"
            "print('running', flush=True)\n"
            f"hertzdash.{kind}({str(data)!r}, cross_validate=True)\n"
            "print('finished', flush=True)\n")
    p = subprocess.Popen([sys.executable, "-c", code], stdout=subprocess.PIPE, stderr=subprocess.PIPE, text=True)
    assert p.stdout.readline().strip() == "running"
    time.sleep(3.0)
    p.send_signal(signal.SIGINT)
    sent = time.monotonic()
    try:
        out, err = p.communicate(timeout=30)
    finally:
        p.kill()
    stopped_after = time.monotonic() - sent
    assert "KeyboardInterrupt" in err, err
    assert "finished" not in out
    assert stopped_after < 5.0


def test_a_number_the_program_writes_as_null_is_none(tmp_path):
    # Issue 45: Python returned inf where the program's JSON has null (JSON has no inf or NaN): a
    # result is the program's JSON, key for key, with None for null.
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        r = hertzdash.simulate(ball_yield_stress=math.inf)
    assert r == cli_json("simulate", "--ball-yield-stress=inf")
    assert all(v is None or math.isfinite(v) for v in numbers_in(r))
    # A rig keeps a number it has none of as NaN, which the program writes as null (docs/shaker.md:
    # e_effective "null: none"): with gamma 0 the body comes to rest and no impact is kept.
    with warnings.catch_warnings():
        warnings.simplefilter("ignore")
        rest = hertzdash.shaker(gamma=0, impacts=5)
    assert rest["e_effective"] is None
    assert all(v is None or math.isfinite(v) for v in numbers_in(rest))


def numbers_in(value):
    if isinstance(value, dict):
        return [x for v in value.values() for x in numbers_in(v)]
    if isinstance(value, list):
        return [x for v in value for x in numbers_in(v)]
    return [value] if isinstance(value, float) or value is None else []


def test_a_path_with_a_nul_is_refused_as_open_refuses_it(tmp_path):
    # Issue 45: C++ cut such a path at the NUL and read or wrote another file.
    for call in (lambda: hertzdash.fit_restitution_table(str(tmp_path / "table.csv") + "\0.txt"),
                 lambda: hertzdash.fit_bounce_times(str(tmp_path / "r.csv\0")),
                 lambda: hertzdash.virtual_measurement(str(tmp_path / "t\0.csv"))):
        with pytest.raises(ValueError, match="embedded null byte"):
            call()
    assert list(tmp_path.iterdir()) == []
