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


# -- ale: flags, material (7 fz_mod), element flags, nm nl nt (byte 1 = 0:
# default), op, mode, kd, p1, L, slope scale, r1, r2 - r1 (/ L), slopes
# (x1', x2', y1', y2'), qd (10), operation arguments --------------------
MAT_STD = (1.3, 5.0, 0.7, 0.15, 0.25, 0.4, -2.1)


def ale(op, mode, kd, L, sc=1.0, eflags=0, extra=b"", flags=0, qd=(0,) * 10,
        slopes=(1, 1, 0, 0), chord=(1, 0)):
    return (B(flags) + Ms(*MAT_STD) + B(eflags, 1, 1, 1, op, mode, kd) +
            M(0) + R(L) + R(sc) + Ms(0, 0) + Ms(*chord) + Ms(*slopes) + Ms(*qd) + extra)


seed("ale", "known_force_tiny_length", ale(0, 0, 3, 1e-100, slopes=(1, 0.5, 0.3, 1), qd=(0.1, 0.2, 0, 0, 0, -0.1, 0.3, 0, 0, 0.05)))
seed("ale", "known_force_huge_slope", ale(0, 0, 3, 1.0, sc=1e100))
# inv chain: op 8, kd bit 2: lengths as any reals; ne = 1; x = 2 nodes, v
seed("ale", "known_inv_chain_force_subnormal_length",
     ale(8, 0, 4 | 3, 1.0, extra=B(0) + R(1e-320) + Ms(0, 0, 1, 0, 1, 0, 1, 0) + Ms(*(0,) * 8)))
seed("ale", "good_force_kd", ale(0, 0, 3, 1.2, qd=(0.1, 0.2, 0, 0, 0, -0.1, 0.3, 0, 0, 0.05)))
seed("ale", "good_mass_jac", ale(2, 0, 0, 0.8, extra=Ms(*(1,) * 10)))
seed("ale", "good_energy_nan_q", ale(3, 0, 0, 1.0, flags=1, chord=(float("nan"), 0)))
seed("ale", "good_point_force_outside", ale(4, 0, 5, 1.0, extra=R(7.0) + Ms(1, 2)))
seed("ale", "good_split", ale(7, 0, 1, 1.0, extra=M(0.3)))
seed("ale", "good_sys_force", ale(9, 0, 3, 1.0, extra=B(1) + Ms(0.5, 0.7) + Ms(0, 0, 1, 0, 0.5, 0, 1, 0, 1.2, 0.1, 1, 0) + Ms(*(0.1,) * 12)))
seed("ale", "good_init_bad_order", B(0) + Ms(*MAT_STD) + B(0, 10, 1, 1))


def main():
    for h, lst in SEEDS.items():
        d = os.path.join(ROOT, h)
        os.makedirs(d, exist_ok=True)
        for name, data in lst:
            with open(os.path.join(d, name), "wb") as f:
                f.write(data)


if __name__ == "__main__":
    main()
