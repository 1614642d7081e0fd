#!/usr/bin/env python3
"""Tests of scripts/bench-bars.py: its readers of each bar's tool output, on
outputs captured from real runs (2026-12-05, main c9cec3b), and its verdicts
against the bars' thresholds. Timing is not tested (benchmarks are not tests).
Registered with ctest (tests/scripts/scripts_tests.cmake)."""

import importlib.util
import os
import sys
import unittest

sys.dont_write_bytecode = True  # no __pycache__ in the source tree
TOP = os.path.dirname(os.path.dirname(os.path.dirname(os.path.abspath(__file__))))
_spec = importlib.util.spec_from_file_location("bench_bars", os.path.join(TOP, "scripts", "bench-bars.py"))
bars = importlib.util.module_from_spec(_spec)
_spec.loader.exec_module(bars)

POVRAY = """| scene | POV-Ray s | raylab s | raylab faster by | per round | POV-Ray CPU s | raylab CPU s | raylab parse | build | render | write | other |
|---|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|---:|
| balls | 1.255 | 0.148 | **8.5×** | 8.3× | 1.150 | 0.275 | 0.004 | 0.004 | 0.127 | 0.007 | 0.014 |
| gears | 1.606 | 0.285 | **5.6×** | 5.6× | 1.844 | 0.545 | 0.012 | 0.004 | 0.243 | 0.006 | 0.016 |
| tetra | 0.791 | 0.045 | **17.5×** | 17.5× | 0.259 | 0.075 | 0.003 | 0.001 | 0.028 | 0.004 | 0.013 |

smallest ratio: 5.6× (gears); per round 5.6× (gears)
"""

LIMIT = """                                                  seconds    Mrays/s    of bare
  bare Embree replay (rtcIntersect1/rtcOccluded1)     0.1868      7.463     100.0%
  replay through Accelerator::intersect/occluded     0.1909      7.301      97.8%
  renderer (full render, shading included)         0.2664      5.233      70.1%

  renderer reaches 70.1% of bare Embree (bar with --spd: >= 80%): NOT met
  run by run (each render against its own replays): median 73.7% (69.3%, 78.3%, 66.2%, 73.7%, 73.8%)
"""

THREADS = """| binary | threads | wall s | CPU s | render s | write s | wall speed-up | write ÷ render |
|---|---:|---:|---:|---:|---:|---:|---:|
| /work/main/build/bin/raylab | 1 | 0.306 | 0.303 | 0.250 | 0.031 | 1.00× | 12% |
| /work/main/build/bin/raylab | 2 | 0.163 | 0.306 | 0.127 | 0.017 | 1.87× | 14% |

/work/main/build/bin/raylab, 1 -> 2 threads, wall speed-up round by round: median 1.87× (1.80–2.03×)
"""

INGEST = """threads  phase                 wall_s      MB/s     cpu_s  cpu_MB/s    bytes/tri
1        loadObj (whole)        0.991      60.7     0.991      60.7        117.3
1        read + parseObj        0.369     163.1     0.368     163.2         54.1
2        loadObj (whole)        0.601     100.0     1.097      54.8        117.1
2        read + parseObj        0.214     280.5     0.389     154.7         54.1
bar (issue 20): loadObj >= 100 MB/s on all cores, peak <= 150 bytes/triangle
"""

REGRESSION = """case                         rgba       exr-bytes flags
demo                         identical  same
demo_naive                   identical  same     --accel naive --width 160 --height 120
textures_eps                 DIFFERENT  differ   --epsilon 1e-4 --robust --bvh-quality high
render failed: new cutouts (see /tmp/x/new/cutouts.log)
cutouts                      identical  same-on-rerun
renders and compare output in /tmp/x
"""


class BenchBars(unittest.TestCase):
    def test_readers(self):
        self.assertEqual(bars.parse_povray(POVRAY),
                         {"balls": (8.5, 8.3), "gears": (5.6, 5.6), "tetra": (17.5, 17.5)})
        self.assertEqual(bars.parse_limit(LIMIT), (70.1, 73.7))
        self.assertEqual(bars.parse_threads(THREADS), (1.87, 1.87, 14.0))
        self.assertEqual(bars.parse_ingest(INGEST), (100.0, 117.1))  # the 2-thread row
        self.assertEqual(bars.parse_regression(REGRESSION), (3, 4))
        self.assertIsNone(bars.parse_limit("raylab: error: x.json:3: bad"))
        self.assertIsNone(bars.parse_threads(""))
        self.assertIsNone(bars.parse_ingest(""))

    def test_verdicts(self):
        rows = bars.verdicts({
            "1": bars.parse_povray(POVRAY),
            "2": (bars.parse_limit(LIMIT), (70.0, 71.0)),
            "3": bars.parse_threads(THREADS),
            "4": bars.parse_ingest(INGEST),
            "5": bars.parse_regression(REGRESSION),
        })
        holds = [h for _, _, h in rows]
        # gears below 6x; balls below 80%; 1.87x with 14%; exactly 100 MB/s
        # holds (>=); one picture differs.
        self.assertEqual(holds, ["no: gears 5.6×", "no", "yes", "yes", "no"])
        self.assertIn("gears 5.6× (5.6×)", rows[0][1])
        self.assertEqual(rows[4][1], "3 of 4 identical")
        # On the lines: every bar exactly at its threshold holds.
        edge = bars.verdicts({"1": {"gears": (6.0, 5.9)}, "2": ((80.0, 79.0), (70.0, 69.0)),
                              "3": (1.8, 1.7, 15.0), "4": (100.0, 150.0), "5": (60, 60)})
        self.assertEqual([h for _, _, h in edge], ["yes"] * 5)
        self.assertEqual([h for _, _, h in bars.verdicts({"2": (None, (75.0, 75.0)), "5": (0, 0)})],
                         ["no", "no"])


if __name__ == "__main__":
    unittest.main()
