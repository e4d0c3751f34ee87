"""Every CSV the suite writes must read with the two conventional calls of the Python world,

    pandas.read_csv(f, comment='#')
    numpy.genfromtxt(f, delimiter=',', names=True, comments='#')

giving the file's own column names and all its rows (io/csv_writer.hpp: the column names on the
first line, the provenance below them as '#' lines).

Usage: check_csv_readers.py LIST, where each line of LIST is "PATH<TAB>COLUMNS<TAB>ROWS": the
file, its column names as hertzdash's own reader (io/csv_table.hpp) read them, comma-separated,
and its number of rows. Prints one line per file that fails and exits 1 if any does.
"""
import sys
import warnings

import numpy as np
import pandas as pd


def problems(path, columns, rows):
    found = []
    frame = pd.read_csv(path, comment="#")
    if list(frame.columns) != columns:
        found.append(f"pandas.read_csv names the columns {list(frame.columns)}, not {columns}")
    if len(frame) != rows:
        found.append(f"pandas.read_csv reads {len(frame)} rows, not {rows}")
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # a row numpy cannot split is a warning, then a lost row
        table = np.atleast_1d(np.genfromtxt(path, delimiter=",", names=True, comments="#", dtype=None,
                                            encoding="utf-8"))
    if list(table.dtype.names) != columns:
        found.append(f"numpy.genfromtxt names the columns {list(table.dtype.names)}, not {columns}")
    if table.shape[0] != rows:
        found.append(f"numpy.genfromtxt reads {table.shape[0]} rows, not {rows}")
    return found


def main(list_path):
    failed = 0
    checked = 0
    with open(list_path, encoding="utf-8") as listing:
        for line in listing:
            path, columns, rows = line.rstrip("\n").split("\t")
            checked += 1
            try:
                found = problems(path, columns.split(","), int(rows))
            except Exception as error:  # a reader that raises fails the file, with its message
                found = [f"{type(error).__name__}: {error}"]
            for p in found:
                print(f"{path}: {p}")
            failed += bool(found)
    print(f"{checked} CSV files read with pandas and numpy, {failed} failed")
    return 1 if failed or checked == 0 else 0


if __name__ == "__main__":
    sys.exit(main(sys.argv[1]))
