#!/usr/bin/python3
"""The bouncing ball on a vibrating table, hertzdash beside Siconos, the nonsmooth-dynamics
reference (`make bench`; the peers' Debian list: debian-packages-peers.txt).

The same ball (e = 0.5, f = 20 Hz, g = 9.80665 m/s^2) at Gamma = 1.3 (the stable period-1 orbit:
cos 2 pi phi = pi (1 - e)/(Gamma (1 + e)), impact speed g T/(1 + e)) and Gamma = 1.6 (past the
period doubling Gamma_2 = 1.5268237: period 2), run by
  - hertzdash: `hertzdash shaker --impact-model instantaneous` (exact flights, certified root
    search for the impacts, simulation/shaker/impact_sequence.hpp);
  - Siconos: its event-driven scheme with Lsodar (siconos_bouncing_ball.py, the force in the
    table's frame a Python callback).
Checks: the same period and impact phases (to 1e-8 of a cycle) and speeds (to 1e-8 m/s) after the
same transient. Prints, per Gamma: the periods, the largest phase and speed differences, and the
time per impact of each (hertzdash's from 200000 impacts less its start-up; Siconos's over its
run). The time per impact is not like for like: Siconos integrates the flights numerically and
calls Python for the force at every step. Exit status 1 when the two disagree.
Usage: siconos_peer.py BUILD_DIR
"""
import json, os, subprocess, sys, time

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import siconos_bouncing_ball as peer  # noqa: E402 (re-executes under /usr/bin/python3 if needed)

E, F_HZ, G = 0.5, 20.0, 9.80665
TRANSIENT, KEPT = 200, 200


def hertzdash(binary, gamma, transient, kept):
    args = [binary, "shaker", "--impact-model", "instantaneous", "--restitution", str(E), "--gamma", str(gamma),
            "--frequency", str(F_HZ), "--gravity", str(G), "--transient", str(transient), "--impacts", str(kept),
            "--json"]
    start = time.perf_counter()
    out = subprocess.run(args, check=True, capture_output=True, text=True).stdout
    return json.loads(out), time.perf_counter() - start


def main():
    if len(sys.argv) != 2:
        sys.exit(__doc__.split("Usage: ")[1])
    binary = os.path.join(sys.argv[1], "hertzdash")
    print("Bouncing ball on a vibrating table, e = %g, f = %g Hz: hertzdash beside Siconos %s (event-driven)"
          % (E, F_HZ, getattr(peer.siconos, "version", "?")))
    print("%6s %9s %9s %14s %14s %14s %14s %8s" % ("Gamma", "period_hd", "period_sk", "max_dphase", "max_dspeed_mps",
                                                   "hd_us_per_imp", "sk_us_per_imp", "ratio"))
    failed = False
    for gamma in (1.3, 1.6):
        run, _ = hertzdash(binary, gamma, TRANSIENT, KEPT)
        times, speeds, seconds, _ = peer.simulate(E, gamma, F_HZ, TRANSIENT + KEPT, G)
        phases = [(t * F_HZ) % 1.0 for t in times[TRANSIENT:]]
        period_sk = peer.period_of(times[TRANSIENT:], phases, F_HZ)
        # The two runs start differently: compare each hertzdash impact with the Siconos impact
        # nearest in phase (the attractor's impacts).
        dphase = max(min(min(abs(p - q), 1 - abs(p - q)) for q in phases) for p in run["impact_phase"])
        dspeed = max(min(abs(u - v) for v in speeds[TRANSIENT:]) for u in run["impact_speed_mps"])
        _, t_long = hertzdash(binary, gamma, 200000, 2)
        _, t_short = hertzdash(binary, gamma, 1, 1)
        hd_us = (t_long - t_short) / 200000 * 1e6
        sk_us = seconds / (TRANSIENT + KEPT) * 1e6
        print("%6.2f %9d %9d %14.2e %14.2e %14.2f %14.1f %8.0f" % (gamma, run["period"], period_sk, dphase, dspeed,
                                                                 hd_us, sk_us, sk_us / hd_us))
        failed = failed or run["period"] != period_sk or dphase > 1e-8 or dspeed > 1e-8
    if failed:
        sys.exit("siconos_peer: hertzdash and Siconos disagree (see above)")


if __name__ == "__main__":
    main()
