"""The registered rigs from Python (simulation/rigs/rig.hpp, python/hertzdash_module.cpp):
hertzdash.run("RIG", **options) and hertzdash.RIG(**options) are `hertzdash RIG --json`, made
from the same rig table and JSON writer, so the dicts are equal to the last bit (JSON carries
doubles with 17 significant digits, which read back exactly); bad input is the program's
refusal as a ValueError naming the keyword.

Run by ctest (test `python_module`) with PYTHONPATH=build/python and HERTZDASH_BIN set.
"""
import json
import math
import os
import subprocess

import pytest

import hertzdash

BIN = os.environ["HERTZDASH_BIN"]


def cli_json(*args):
    r = subprocess.run([BIN, *args, "--json"], capture_output=True, text=True)
    assert r.returncode == 0, r.stderr
    return json.loads(r.stdout)


def test_every_rig_is_a_function_and_a_command():
    assert hertzdash.rigs() == ["shaker", "walls", "oscillator", "spheres", "oblique"]
    for rig in hertzdash.rigs():
        assert callable(getattr(hertzdash, rig))
        assert subprocess.run([BIN, rig, "--help"], capture_output=True).returncode == 0


def test_oscillator_gives_the_programs_numbers():
    # The impact oscillator's default stop (inside the steady amplitude) with e = 0.7: Python's
    # function, hertzdash.run and the command give the same JSON; Newton's law gives e_effective = e.
    kw = dict(impact_model="instantaneous", restitution=0.7, stop_distance=0.002, impacts=4, transient=100)
    d = hertzdash.oscillator(**kw)
    assert d == hertzdash.run("oscillator", **kw)
    assert d == cli_json("oscillator", "--impact-model", "instantaneous", "--restitution", "0.7", "--stop-distance",
                         "0.002", "--impacts", "4", "--transient", "100")
    assert d["e_effective"] == pytest.approx(0.7, rel=1e-12)
    assert len(d["impact_phase"]) == 4


def test_two_beads_give_the_programs_numbers():
    # Two glass beads head-on (the README's example): the function, hertzdash.run and the command
    # agree; equal spheres leave with v (1 -+ e)/2 in the frame where the second rested.
    kw = dict(density=2500, ball_radius=1e-3, ball_E=63e9, ball_nu=0.22, restitution=0.9, impact_velocity=1,
              damping="tsuji-dem")
    d = hertzdash.spheres(**kw)
    assert d == hertzdash.run("spheres", **kw)
    assert d == cli_json("spheres", "--density", "2500", "--ball-radius", "1e-3", "--ball-E", "63e9", "--ball-nu", "0.22",
                         "--restitution", "0.9", "--impact-velocity", "1", "--damping", "tsuji-dem")
    assert d["e_effective"] == pytest.approx(0.9, rel=1e-6)
    assert d["second_velocity_after_mps"] == pytest.approx(0.95, rel=1e-6)
    with pytest.raises(ValueError, match="second_density"):
        hertzdash.spheres(**kw, second_mass=1e-3, second_density=7800)


def test_oblique_two_spheres_give_the_programs_numbers():
    # Two glass beads at 30 degrees (hertzdash oblique --second-radius): the function, hertzdash.run
    # and the command agree. Counter-spinning with no slip (Chung and Ooi's test 7), head-on: no
    # tangential force, so both spins leave unchanged and no tangential velocity appears.
    kw = dict(density=2500, ball_radius=1e-3, ball_E=63e9, ball_nu=0.22, restitution=0.9, impact_velocity=1,
              damping="tsuji-dem", incidence_angle=30, friction=0.2, second_radius=2e-3)
    d = hertzdash.oblique(**kw)
    assert d == hertzdash.run("oblique", **kw)
    assert d == cli_json("oblique", "--density", "2500", "--ball-radius", "1e-3", "--ball-E", "63e9", "--ball-nu", "0.22",
                         "--restitution", "0.9", "--impact-velocity", "1", "--damping", "tsuji-dem", "--incidence-angle",
                         "30", "--friction", "0.2", "--second-radius", "2e-3")
    # Friction slows the first sphere's tangential motion and drags the second along.
    w0 = math.sin(math.radians(30))
    assert 0 < d["second_tangential_velocity_after_mps"] < d["tangential_velocity_after_mps"] < w0
    spin = hertzdash.oblique(**dict(kw, incidence_angle=0, spin=40, second_spin=-20))
    assert spin["rebound_angular_velocity_rad_per_s"] == 40
    assert spin["second_rebound_angular_velocity_rad_per_s"] == -20
    assert spin["tangential_velocity_after_mps"] == 0
    with pytest.raises(ValueError, match="second_spin"):
        hertzdash.oblique(**{k: v for k, v in kw.items() if k != "second_radius"}, second_spin=1)


def test_shaker_gives_the_programs_numbers():
    # The instantaneous map (e = 0.5) just above its period-doubling threshold
    # sqrt((pi/3)^2 + (10/9)^2) = 1.5268 (docs/shaker.md): period 2, e_effective = e exactly.
    kw = dict(impact_model="instantaneous", restitution=0.5, gamma=1.55, impacts=4, transient=2000)
    d = hertzdash.shaker(**kw)
    assert d == hertzdash.run("shaker", **kw)
    assert d == cli_json("shaker", "--impact-model", "instantaneous", "--restitution", "0.5", "--gamma", "1.55",
                         "--impacts", "4", "--transient", "2000")
    assert d["period"] == 2 and d["e_effective"] == pytest.approx(0.5, rel=1e-12)
    assert len(d["impact_phase"]) == 4


def test_soft_shaker_gives_the_programs_numbers():
    kw = dict(restitution=0.5, gamma=1.3, impacts=2, transient=50, frequency=25)
    assert hertzdash.shaker(**kw) == cli_json("shaker", "--restitution", "0.5", "--gamma", "1.3", "--impacts", "2",
                                              "--transient", "50", "--frequency", "25")


def test_walls_damper_gives_the_programs_numbers_and_balances_energy():
    kw = dict(rig="damper", impact_model="instantaneous", gravity=0, restitution=0.6, primary_damping_ratio=0.05,
              impacts=4, transient=400)
    d = hertzdash.walls(**kw)
    assert d == hertzdash.run("walls", **kw)
    assert d == cli_json("walls", "--rig", "damper", "--impact-model", "instantaneous", "--gravity", "0",
                         "--restitution", "0.6", "--primary-damping-ratio", "0.05", "--impacts", "4",
                         "--transient", "400")
    # The damper's energy account (simulation/shaker/two_walls.hpp): W - D - L = E(end) - E(0),
    # each a sum of Gauss-Legendre quadratures and closed forms: to round-off of the work.
    E = d["energy_J"]
    assert E["drive_work"] - E["damping_dissipation"] - E["impact_loss"] == \
        pytest.approx(E["final"] - E["initial"], abs=1e-9 * abs(E["drive_work"]))
    assert set(d["wall"]) == {"floor", "ceiling"}


def test_bad_rig_input_is_a_value_error_naming_the_keyword():
    with pytest.raises(ValueError, match="gamma"):
        hertzdash.shaker(gamma=1.3, amplitude=1e-3)
    with pytest.raises(ValueError, match="impact_velocity"):
        hertzdash.shaker(impact_velocity=1.0)
    with pytest.raises(ValueError, match="rig"):
        hertzdash.run("drum")
    with pytest.raises(TypeError, match="bogus"):
        hertzdash.walls(bogus=1)
    # An unknown keyword lists the rig's own inputs beside the options.
    with pytest.raises(TypeError, match="inputs: frequency, amplitude, gamma, impacts"):
        hertzdash.shaker(bogus=1)
    with pytest.raises(ValueError, match="impacts"):
        hertzdash.walls(impacts=2.5)


def test_orbit_is_the_programs_orbit():
    # hertzdash.orbit("RIG", ...) is `hertzdash orbit RIG --json` (docs/orbits.md). The bouncing
    # ball's stable period-1 orbit at e = 0.5, Gamma = 1.3 has the multipliers
    # -0.24159860 +- 0.43775577i (tests/test_orbits.cpp derives them), modulus e.
    # Its impact model is instantaneous unless told.
    kw = dict(restitution=0.5, gamma=1.3)
    d = hertzdash.orbit("shaker", **kw)
    assert d == cli_json("orbit", "shaker", "--restitution", "0.5", "--gamma", "1.3")
    assert d["converged"] and d["stable"] and d["period"] == 1
    assert d["multipliers"][0][0] == pytest.approx(-0.24159860, abs=1e-8)
    assert abs(d["multipliers"][0][1]) == pytest.approx(0.43775577, abs=1e-8)
    # The orbit's own options are keywords; a guess needs both halves, refused naming the missing one.
    with pytest.raises(ValueError, match="guess_velocity"):
        hertzdash.orbit("shaker", section_phase=0.5, guess_position=0.003, **kw)
    with pytest.raises(ValueError, match="shaker, walls, oscillator"):
        hertzdash.orbit("bounce")
    # The damper's section is four-dimensional: the primary's half of a guess is asked for by name.
    damper = hertzdash.orbit("walls", rig="damper")
    assert damper == cli_json("orbit", "walls", "--rig", "damper")
    assert set(damper["section_state"]) == {"position_m", "velocity_mps", "box_position_m", "box_velocity_mps"}
    with pytest.raises(ValueError, match="guess_box_position"):
        hertzdash.orbit("walls", rig="damper", section_phase=0.5, guess_position=0.005, guess_velocity=0)
    # No orbit to find (the body sticks to the wall once a period): a warning, and the dict says why.
    with pytest.warns(UserWarning, match="no periodic orbit found"):
        stuck = hertzdash.orbit("shaker", restitution=0.5, gamma=1.02)
    assert not stuck["converged"] and "sticks to the wall" in stuck["failure"]


def test_continuation_is_the_programs_continue():
    # hertzdash.continuation("RIG", ...) is `hertzdash continue RIG --json`; `from` is the Python
    # argument from_. The shaker's period doubling lies at the closed form
    # Gamma_2 = sqrt((pi/3)^2 + (10/9)^2) for e = 0.5 (tests/test_orbits.cpp).
    d = hertzdash.continuation("shaker", restitution=0.5, parameter="gamma", from_=1.3, to=1.6)
    assert d == cli_json("continue", "shaker", "--restitution", "0.5", "--parameter", "gamma", "--from", "1.3",
                         "--to", "1.6")
    assert [e["type"] for e in d["events"]] == ["period-doubling"]
    assert d["events"][0]["parameter"] == pytest.approx(math.hypot(math.pi / 3, 10 / 9), abs=1e-8)
    assert {p["period"] for p in d["branch"]} == {1, 2}
    with pytest.raises(ValueError, match="parameter"):
        hertzdash.continuation("shaker", parameter="impacts", from_=1, to=2)


def test_basins_is_the_programs_basins():
    # e = 0.8, Gamma = 0.8: the period-1 orbit (impact phase acos(Gamma_1/Gamma)/(2 pi), Gamma_1 =
    # pi (1 - e)/(1 + e)) and the body at rest on the table share the section (tests/test_orbit_basins.cpp).
    grid = dict(restitution=0.8, gamma=0.8, resolution=6, position_min=6e-4, position_max=0.02,
                velocity_min=-0.5, velocity_max=0.5)
    d = hertzdash.basins("shaker", threads=1, **grid)
    assert d == cli_json("basins", "shaker", "--restitution", "0.8", "--gamma", "0.8", "--resolution", "6",
                         "--position-min", "6e-4", "--position-max", "0.02", "--velocity-min", "-0.5",
                         "--velocity-max", "0.5", "--threads", "1")
    kinds = {a["kind"] for a in d["attractors"]}
    assert {"periodic", "rest"} <= kinds
    phase = math.acos(math.pi * 0.2 / 1.8 / 0.8) / (2 * math.pi)
    periodic = [a for a in d["attractors"] if a["kind"] == "periodic" and a["period"] == 1]
    assert periodic and periodic[0]["impact_phase"][0] == pytest.approx(phase, abs=1e-9)


def test_lyapunov_is_the_programs_lyapunov():
    # A chaotic bouncing ball (e = 0.95, Gamma = 2.2): its exponents sum to 2 ln e per impact.
    d = hertzdash.lyapunov("shaker", restitution=0.95, gamma=2.2, periods=3000)
    assert d == cli_json("lyapunov", "shaker", "--restitution", "0.95", "--gamma", "2.2", "--periods", "3000")
    assert d["sum_per_impact"] == pytest.approx(2 * math.log(0.95), abs=1e-10)
    assert d["exponents_per_impact"][0] > 0
