#!/usr/bin/env python3
"""seeds.py -- writes the hand-made seeds of fuzz/corpus/<harness>/ in the
input format of fuzz/fuzz_util.h (part of vlbe, SPDX-License-Identifier: MIT).

    python3 fuzz/seeds.py          (from the repository root)

Seeds named known_* reproduce the contract violations of the base code
77b73ad listed when the fuzzing started, found_* those the harnesses found
(the replay test fails on both until the library is fixed); good_* are
inputs the base code handles as the contract says.  Inputs found by the
fuzzer are copied into the corpus by hand (minimised)."""
import os
import struct

ROOT = os.path.join(os.path.dirname(os.path.abspath(__file__)), "corpus")


def R(x):
    """a real as class 7 (raw IEEE double)"""
    return b"\x07" + struct.pack("<d", float(x))


def Rs(*xs):
    return b"".join(R(x) for x in xs)


def M(x):
    """a moderate real (fz_mod) given exactly: the escape to fz_real"""
    return b"\x07" + R(x)


def Ms(*xs):
    return b"".join(M(x) for x in xs)


def B(*bs):
    return bytes(bs)


def I32(v):
    return struct.pack("<i", v)


SEEDS = {}


def seed(h, name, data):
    SEEDS.setdefault(h, []).append((name, data))


# -- lu: flags, n-1, structure, entries, nrhs-1, rhs ---------------------
def lu(flags, n, s, A, b):
    return B(flags, n - 1, s) + Rs(*A) + (B(0) if n > 1 else b"") + B(0) + Ms(*b)


seed("lu", "known_tiny_pivot_nan", lu(0, 2, 0, [1e-322, 0, 0, 0], [1, 1]))
seed("lu", "known_huge_inf", lu(0, 2, 0, [1e308, 1e308, -1e308, 1e308], [1, 1]))
seed("lu", "known_float_subnormal_pivot", lu(0, 2, 0, [1e-39, 0, 0, 0], [1, 1]))
seed("lu", "good_identity3", lu(0, 3, 0, [1, 0, 0, 0, 1, 0, 0, 0, 1], [1, 2, 3]))
seed("lu", "good_pivoting3", lu(0, 3, 0, [0, 2, 1, 1, 1, 1, 4, -1, 3], [1, -2, 0.5]))
seed("lu", "found_info_zeroed_on_enonfinite", lu(1, 2, 0, [1, float("nan"), 0, 1], [1, 1]))
seed("lu", "found_piv_written_on_esingular", lu(2, 3, 2, [1, 2, 3, 4, 5, 6, 7, 8, 10], [1, 1, 1]))


def main():
    for h, lst in SEEDS.items():
        d = os.path.join(ROOT, h)
        os.makedirs(d, exist_ok=True)
        for name, data in lst:
            with open(os.path.join(d, name), "wb") as f:
                f.write(data)


if __name__ == "__main__":
    main()
