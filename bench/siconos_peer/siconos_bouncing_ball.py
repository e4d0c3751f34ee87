#!/usr/bin/python3
"""Bouncing ball on a vibrating table, run with Siconos's EVENT-DRIVEN scheme.

Peer reference: Siconos (siconos.kernel, Debian python3-siconos 4.4): EventDriven
simulation + LsodarOSI (ODEPACK DLSODAR with root finding) + LCP at impact level
(SICONOS_OSNSP_ED_IMPACT) and acceleration level (SICONOS_OSNSP_ED_SMOOTH_ACC).

Physics (SI): table X(t) = A sin(w t), w = 2 pi f, A = Gamma g / w^2, m = 1, g = 9.81
(--gravity; the project's own runs use 9.80665).
Table frame, x = y - X(t) >= 0:   x'' = -g + A w^2 sin(w t)   (while x > 0)
Impact (Newton, relative velocity): x'(t+) = -e x'(t-)  <=>  u+ - V = -e (u- - V).
Siconos model: LagrangianLinearTIDS (M = 1) subclassed in Python; SWIG directors make
Siconos call our computeFExt(t) for the time-dependent force.  Relation
LagrangianLinearTIR (y = x), law NewtonImpactNSL(e).
Start: released from rest (lab frame) at height g T^2/8 above the mean table at drive
phase 0.5 (T = 1/f), i.e. x(t0) = g T^2/8, x'(t0) = -X'(t0) = A w, t0 = T/2.
(The phase-0 release chatters into sticking, which Siconos 4.4 ED cannot pass with a
time-dependent force; see the error message below.)

Closed-form check (period-1 orbit, one impact per drive cycle):
  cos(2 pi phase) = pi (1-e) / (Gamma (1+e)), sin > 0;  impact speed = g T / (1+e).
  e=0.5, Gamma=1.3, f=20: phase 0.10093859, speed 0.327 m/s (0.32688833 m/s with
  g = 9.80665); it period-doubles at
  Gamma_2 = sqrt((pi(1-e)/(1+e))^2 + (2(1+e^2)/(1+e)^2)^2) = 1.5268237.

Prints one JSON object on stdout: engine, version, scheme, restitution, gamma,
frequency_Hz, gravity_mps2, impacts, impact_phases (frac(t f)), impact_speeds_mps (relative,
pre-impact), period_cycles (smallest p in 1..16 with phases repeating every p impacts
to 1e-6 and times differing by whole drive cycles, else 0), seconds (integration
loop wall time), seconds_per_impact, plus the period-1 closed form and tolerances.
Usage: siconos_bouncing_ball.py --restitution E --gamma G --frequency F --impacts N
       --transient M [--gravity g]   (exit status 1 + message on stderr on any failure)
"""
import argparse, json, math, os, sys, time

try:
    import numpy as np
    import siconos
    import siconos.kernel as sk
except ImportError as exc:  # e.g. a pyenv python3 first on PATH: use Debian's python
    if os.path.exists("/usr/bin/python3") and sys.executable != "/usr/bin/python3":
        os.execv("/usr/bin/python3", ["/usr/bin/python3"] + sys.argv)
    sys.exit("siconos_bouncing_ball: cannot import siconos (%s)" % exc)

def period_of(times, phases, f, tol=1e-6, pmax=16):
    for p in range(1, pmax + 1):
        if len(phases) <= p:
            break
        ok = True
        for i in range(len(phases) - p):
            dph = abs(phases[i + p] - phases[i])
            cyc = (times[i + p] - times[i]) * f
            if min(dph, 1.0 - dph) > tol or abs(cyc - round(cyc)) > tol or round(cyc) < 1:
                ok = False
                break
        if ok:
            return p
    return 0


def simulate(e, gamma, f, n_total, g):
    w = 2.0 * math.pi * f
    T = 1.0 / f
    A = gamma * g / w**2

    class TableFrameBall(sk.LagrangianLinearTIDS):
        def computeFExt(self, t):  # called back by Siconos (SWIG director)
            self.fExt()[0] = -g + A * w * w * math.sin(w * t)

    t0 = 0.5 * T
    ball = TableFrameBall([g * T * T / 8.0], [A * w], np.eye(1))
    ball.setFExtPtr([-g])  # allocates fExt; overwritten by computeFExt(t)
    inter = sk.Interaction(sk.NewtonImpactNSL(e), sk.LagrangianLinearTIR(np.eye(1)))
    nsds = sk.NonSmoothDynamicalSystem(t0, t0 + 50.0 * T * (n_total + 10))
    nsds.insertDynamicalSystem(ball)
    nsds.link(inter, ball)
    osi = sk.LsodarOSI()  # default DLSODAR tolerances: rtol = 10 eps, atol = 100 eps
    simu = sk.EventDriven(nsds, sk.TimeDiscretisation(t0, 10.0 * T))
    simu.insertIntegrator(osi)
    simu.insertNonSmoothProblem(sk.LCP(), sk.SICONOS_OSNSP_ED_IMPACT)
    simu.insertNonSmoothProblem(sk.LCP(), sk.SICONOS_OSNSP_ED_SMOOTH_ACC)
    events = simu.eventsManager()
    times, speeds = [], []
    start = time.perf_counter()
    try:
        while simu.hasNextEvent() and len(times) < n_total:
            simu.advanceToEvent()  # Lsodar up to next time-grid point or root (impact)
            ev = events.nextEvent()
            if ev.getType() == sk.NS_EVENT:  # state is still pre-impact here
                times.append(ev.getDoubleTimeOfEvent())
                speeds.append(-ball.velocity()[0])
            simu.processEvents()  # impact LCP, Newton law, acceleration LCP
    except Exception as exc:
        last = "t=%.9g s, speed %.3g m/s" % (times[-1], speeds[-1]) if times else "none"
        raise RuntimeError(
            "Siconos EventDriven failed after %d impacts (last impact %s): %s. A tiny "
            "last speed means an accumulation of impacts (chattering) ending in sticking;"
            " with a time-dependent force Siconos 4.4 solves the acceleration LCP with a "
            "stale free acceleration and throws in updateIndexSetsWithDoubleCondition "
            "or Lsodar stops with istate=-1." % (len(times), last, exc))
    seconds = time.perf_counter() - start
    if len(times) < n_total:
        raise RuntimeError("only %d of %d impacts before the end time" % (len(times), n_total))
    return times, speeds, seconds, simu.toleranceED()


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--restitution", type=float, default=0.5)
    ap.add_argument("--gamma", type=float, default=1.3)
    ap.add_argument("--frequency", type=float, default=20.0)
    ap.add_argument("--impacts", type=int, default=200)
    ap.add_argument("--transient", type=int, default=200)
    ap.add_argument("--gravity", type=float, default=9.81)
    a = ap.parse_args()
    if not (0.0 <= a.restitution < 1.0 and a.gamma > 0 and a.frequency > 0 and a.gravity > 0
            and a.impacts > 0 and a.transient >= 0):
        raise ValueError("need 0 <= e < 1, gamma > 0, frequency > 0, impacts > 0, transient >= 0")
    e, f = a.restitution, a.frequency
    times, speeds, seconds, tol_ed = simulate(e, a.gamma, f, a.transient + a.impacts, a.gravity)
    times, speeds = times[a.transient:], speeds[a.transient:]
    phases = [math.fmod(t * f, 1.0) for t in times]
    out = {"engine": "siconos", "version": getattr(siconos, "version", "unknown"),
           "scheme": "event-driven", "restitution": e, "gamma": a.gamma,
           "frequency_Hz": f, "gravity_mps2": a.gravity, "impacts": len(times), "impact_phases": phases,
           "impact_speeds_mps": speeds, "period_cycles": period_of(times, phases, f),
           "seconds": seconds, "seconds_per_impact": seconds / (a.transient + a.impacts),
           "integrator": "LsodarOSI (DLSODAR) default rtol=10*eps atol=100*eps, "
                         "EventDriven TOL_ED=%.3g" % tol_ed}
    c = math.pi * (1.0 - e) / (a.gamma * (1.0 + e))
    if c <= 1.0:  # period-1 orbit exists (stable only below Gamma_2)
        ph1, u1 = math.acos(c) / (2.0 * math.pi), a.gravity / (f * (1.0 + e))
        dph = max(min(abs(p - ph1), 1.0 - abs(p - ph1)) for p in phases)
        out["closed_form_period1"] = {"phase": ph1, "speed_mps": u1, "max_abs_phase_dev": dph,
                                      "max_abs_speed_dev_mps": max(abs(s - u1) for s in speeds)}
    json.dump(out, sys.stdout)
    sys.stdout.write("\n")


if __name__ == "__main__":
    try:
        main()
    except Exception as exc:
        sys.stderr.write("siconos_bouncing_ball: error: %s\n" % exc)
        sys.exit(1)
