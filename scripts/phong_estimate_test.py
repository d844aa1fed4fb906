#!/usr/bin/env python3
"""The arithmetic of scripts/phong_estimate.py against values worked by hand (no value here comes
from the code under test), and its readers on small files written here."""
import os
import sys
import tempfile
import unittest

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
import phong_estimate as pe  # noqa: E402


class Arithmetic(unittest.TestCase):
    # Units: mul 100 transistors, add 10, an array 48 (worked below); device 1000 transistors, 9
    # clocks a sample; clock 10 ns.
    unit = {"mul": ("m", 100, 0, 3.0), "add": ("a", 10, 0, 1.0), "div": ("d", 48, 0, 5.6), "sqrt": ("s", 48, 0, 5.6)}
    phong = {"mul": 2.0, "div": 1.0, "sqrt": 1.0, "add": 4.0, "samples": 0.5}
    geometry = {"mul": 1.0, "div": 0.0, "sqrt": 0.0, "add": 2.0}

    def test_phong(self):
        # 2 x 100 + 1 x 48 + 1 x 48 + 4 x 10 = 336, devices 0.5 x 9 = 4.5 x 1000 = 4500: 4836 at 10 ns.
        est = pe.estimate(self.phong, self.geometry, self.unit, (1000, 9), 10.0, {})
        self.assertEqual(est["phong"], (4836.0, 1.0, 10.0, 48360.0))

    def test_pipeline(self):
        # Top 2000; geometry at 4 clocks a pixel: 1/4 multiplier (25) + 2/4 adder (5) = 2030, 40 ns a
        # pixel, 81 200 transistor-ns.
        est = pe.estimate(self.phong, self.geometry, self.unit, (1000, 9), 10.0, {"p": (2000, 4.0)})
        self.assertEqual(est["p"], (2030.0, 4.0, 40.0, 81200.0))

    def test_array_units(self):
        # 4 stages of (inverter bank 1 + subtractor 8 + multiplexer 3) = 48 transistors, depth
        # 4 x (1 + 5 + 2) = 32 gates, 4 x (0.1 + 1 + 0.3) = 5.6 ns; mul and add their rows and the model's.
        rows = {"phong_mul_5": (100, 9), "phong_add_8": (10, 4), "phong_stage_inv_5": (1, 1),
                "phong_stage_sub_5": (8, 5), "phong_stage_mux_4": (3, 2), "sqmul_saturate": (1000, 40)}
        dl = {"multiplier": 3.0, "adder": 1.0, "mux": 0.3, "inverter": 0.1}
        u = pe.units(rows, dl)
        self.assertEqual(u["mul"][1:], (100, 9, 3.0))
        self.assertEqual(u["add"][1:], (10, 4, 1.0))
        self.assertEqual(u["div"][1:3], (48, 32))
        self.assertAlmostEqual(u["div"][3], 5.6)
        self.assertEqual(u["sqrt"][1:3], (48, 32))
        # A second, wider multiplier: the narrowest by default, the other by its width.
        rows["phong_mul_12"] = (700, 20)
        self.assertEqual(pe.units(rows, dl)["mul"][1], 100)
        self.assertEqual(pe.units(rows, dl, 12)["mul"][1], 700)

    def test_readers(self):
        with tempfile.TemporaryDirectory() as d:
            t = os.path.join(d, "timing.txt")
            with open(t, "w") as f:
                f.write("shading_pipeline<sqmul_device, horner>: x\n  shortest period: 50 % duty 12.80 ns (78.1 MHz)\n"
                        "shading_pipeline<sqmul_device, fd> (fd_m 0): x\n  shortest period: 50 % duty 9.50 ns\n")
            self.assertEqual(pe.pipeline_period(t, "horner"), 12.8)
            self.assertEqual(pe.pipeline_period(t, "fd"), 9.5)
            h = os.path.join(d, "comb_delay.h")
            with open(h, "w") as f:
                f.write("inline const sc_core::sc_time adder{1000, sc_core::SC_PS};\n"
                        "inline const sc_core::sc_time mux{300, sc_core::SC_PS};\n")
            self.assertEqual(pe.delays_ns(h), {"adder": 1.0, "mux": 0.3})


if __name__ == "__main__":
    unittest.main()
