"""The README's work-precision figure, docs/tradeoff_t_handle.png: the main job
(`python3 -m rigiddyn tradeoff t_handle`, the shipped problem's own sweep) plotted as the CLI's --out
does, with how it was made (command, date, machine, digest of INPUTS) in the PNG's text chunks.

  PYTHONPATH=build/<dir>/python python3 bench/python/plot_tradeoff_t_handle.py [--out FILE.png]

tests/python/test_generated_docs.py fails once an input differs from what the figure was made from.
"""

from __future__ import annotations

import argparse
import sys
import warnings
from pathlib import Path

import rigiddyn
from provenance import ROOT, SIMULATION_INPUTS, png_stamp, stamp

OUT = ROOT / "docs" / "tradeoff_t_handle.png"
# this script, the problem file, and the Python (the sweep and its plot) and C++ the runs execute
INPUTS = ["bench/python/plot_tradeoff_t_handle.py", "python/rigiddyn/problems/t_handle.toml", *SIMULATION_INPUTS]
REGENERATE = ("cmake --build build/<dir> --target _core && "
              "PYTHONPATH=build/<dir>/python python3 bench/python/plot_tradeoff_t_handle.py  (a few seconds)")


def main(argv=None) -> int:
    parser = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    parser.add_argument("--out", type=Path, default=OUT, help="PNG file (default: docs/tradeoff_t_handle.png)")
    args = parser.parse_args(argv)
    made = stamp(INPUTS)  # the inputs as the run starts, and the machine's load then
    with warnings.catch_warnings():
        warnings.simplefilter("ignore", rigiddyn.StabilityWarning)  # the table marks those runs
        result = rigiddyn.tradeoff("t_handle", progress=False)
    print(result.to_table())
    (png,) = result.plot(args.out.with_suffix(""), formats=["png"])
    png_stamp(png, made)
    print(f"wrote {png}")
    return 0


if __name__ == "__main__":
    sys.exit(main())
