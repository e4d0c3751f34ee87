#!/usr/bin/env python3
"""Fig. 5(a) of Hongo et al. from Python: the contact force of the steel rod dropped
20 mm onto the nylon hemisphere, from the paper's model with the nylon modulus at its
assumed value and at both ends of the catalogue range of Table 3.

    PYTHONPATH=build/python python3 examples/fig5_force.py [--out fig5a.png]

Prints the peak force of each curve; with --out, draws the panel with matplotlib (if it is
installed). No measured curve is drawn: the paper printed its
measurements only as plots, and no machine-readable copy exists (data/measurements/).
"""
import argparse
import os

import hertzdash


def curves(height_m=0.02, rod="steel"):
    """The force trace on a 1 us grid for the assumed and the two catalogue moduli."""
    ball = hertzdash.paper_parameters()["ball"]
    moduli = {"assumed": ball["E_Pa"], "catalogue min": ball["E_min_Pa"], "catalogue max": ball["E_max_Pa"]}
    return {label: (E, hertzdash.trace(grid_step=1e-6, rod=rod, height=height_m, ball_E=E)) for label, E in moduli.items()}


def main():
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", help="draw the panel into this image file (needs matplotlib)")
    args = parser.parse_args()

    results = curves()
    for label, (E, t) in results.items():
        print(f"nylon E = {E:.3g} Pa ({label}): peak force {t['force_N'].max():.6g} N")

    if args.out:
        try:
            import matplotlib
        except ImportError:
            print(f"matplotlib is not installed: {args.out} not drawn")
            return
        matplotlib.use("Agg")
        import matplotlib.pyplot as plt
        fig, ax = plt.subplots(figsize=(5, 3.5))
        for label, (E, t) in results.items():
            ax.plot(1e3 * (t["t_s"] - t["t_s"][0]), t["force_N"], label=f"E = {E / 1e9:.1f} GPa ({label})")
        ax.set_xlabel("time from contact onset [ms]")
        ax.set_ylabel("contact force [N]")
        ax.set_title("Steel rod, h = 20 mm: the paper's model (hertzdash)")
        ax.legend()
        fig.tight_layout()
        # Written whole or not at all: drawn into a temporary file, then renamed.
        root, ext = os.path.splitext(args.out)
        partial = f"{root}.partial{ext}"
        fig.savefig(partial)
        os.replace(partial, args.out)


if __name__ == "__main__":
    main()
