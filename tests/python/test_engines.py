"""The discrete-element engines from Python (docs/engines.md): the same decks and rows as the program."""
import json
import os
import subprocess

import pytest

import hertzdash

BEAD = dict(mass=1.0471975511965977e-5, ball_radius=1e-3, ball_E=63e9, ball_nu=0.22, rod_E=200e9, rod_nu=0.3,
            restitution=0.9, impact_velocity=1.0)


def test_export_decks_writes_what_the_program_writes(tmp_path):
    r = hertzdash.export_decks("liggghts", str(tmp_path), damping="tsuji-dem", **BEAD)
    assert r["hertzdash_law"] == "tsuji-dem" and r["engine_model"] == "hertz"
    assert sorted(os.listdir(tmp_path)) == ["contact_lines.in", "sphere_sphere.in", "sphere_wall.in"]
    program = os.environ["HERTZDASH_BIN"]
    cli_dir = tmp_path / "cli"
    cli_dir.mkdir()
    args = [program, "export", "--engine", "liggghts", "--damping", "tsuji-dem", "--out", str(cli_dir), "--json"]
    for key, value in BEAD.items():
        args += ["--" + key.replace("_", "-"), repr(value)]
    cli = json.loads(subprocess.run(args, check=True, capture_output=True, text=True).stdout)
    assert [i["restitution"] for i in cli["impacts"]] == [i["restitution"] for i in r["impacts"]]
    deck = (tmp_path / "sphere_wall.in").read_text().split("\n")
    assert [l for l in deck if not l.startswith("#")] == [
        l for l in (cli_dir / "sphere_wall.in").read_text().split("\n") if not l.startswith("#")]


def test_conformance_rows_and_bad_input():
    rows = hertzdash.conformance("liggghts", steps_per_contact=100, **BEAD)["rows"]
    assert len(rows) == 6
    for row in rows:
        # tsuji-dem's error bound at N = 100: 0.3 N^-1.25 (docs/engines.md).
        assert abs(row["e_engine"] - row["e_hertzdash"]) < 0.3 * 100 ** -1.25
    with pytest.raises(ValueError, match="engine"):
        hertzdash.conformance("abaqus", **BEAD)
    with pytest.raises(ValueError, match="steps_per_contact"):
        hertzdash.conformance("lammps", steps_per_contact=5, **BEAD)
    with pytest.raises(ValueError, match="out"):
        hertzdash.export_decks("lammps", "/no/such/directory", damping="tsuji-dem", **BEAD)
