#!/usr/bin/env python3
"""seeds.py -- writes the hand-made seeds of fuzz/corpus/<harness>/ in the
input format of fuzz/fuzz_util.h (part of vlbe, SPDX-License-Identifier: MIT).

    python3 fuzz/seeds.py          (from the repository root)

Seeds named known_* reproduce contract violations of 77b73ad that were
found by hand, found_* those the harnesses found (both are regression
inputs: the replay test failed on them at 77b73ad); good_* are inputs that
code already handled as the contract says.  Inputs found by the
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


# -- rancf: flags, op, d, kd, w (4), l, x (4 d moderate), arguments ------
def rancf(op, d, kd, w, l, x, extra=b"", flags=0):
    return B(flags, op, d, kd) + Rs(*w) + R(l) + Ms(*x) + extra


X8 = (0, 0, 1, 0, 1, 0.2, 1, 0)
seed("rancf", "known_to_bezier_weight_ratio", rancf(0, 2, 0, (1e300, 1e-300, 1, 1), 1.0, X8))
seed("rancf", "known_bezier_split_weight_ratio", rancf(3, 2, 0, (1e-300, 1, 1, 1e300), 0.5, X8))
seed("rancf", "good_to_bezier_unit", rancf(0, 2, 0, (1, 1, 1, 1), 1.0, X8))
seed("rancf", "good_from_bezier_bad_d", rancf(1, 4, 0, (1, 0.8, 0.8, 1), 1.0, X8))
seed("rancf", "good_split_arc_weights", rancf(3, 2, 0, (1, 0.805, 0.805, 1), 0.3, X8))
seed("rancf", "good_negative_weight", rancf(2, 2, 0, (1, -1, 1, 1), 0.3, X8))


# -- cr2d: flags, material (EA, EI, rhoA, rhoI, ray_a, ray_b), X1, X2 - X1,
# element flags, op, mode, kd, q displacements (3 per node), q', args ----
def cr2d(dX, op, kd=3, extra=b"", flags=0):
    return (B(flags) + Ms(100, 1, 1, 0.01, 0.1, 0.01) + Ms(0, 0) + Rs(*dX) + B(0, op, 0, kd) +
            Ms(0.01, 0, 0.1, 0, 0.02, -0.1) + Ms(0.1, 0, 0, 0, 0.1, 0.2) + extra)


seed("cr2d", "known_elem_init_tiny_chord", cr2d((1e-120, 0), 0))
seed("cr2d", "known_beam_init_ne_int_max", cr2d((1, 0), 8, extra=B(2, 0)))
seed("cr2d", "good_force", cr2d((1, 0.5), 0))
seed("cr2d", "good_trans_force", cr2d((1, 0), 4, extra=Ms(0, 0.5, 0)))
seed("cr2d", "good_beam_init_bad_dof", cr2d((1, 0), 8, extra=B(9, 3, 1, 1, 0, 9, 2)))


# -- chain: flags, nn - 2, spare capacity, nodes (mode byte, dp, [p0], pd,
# pdd), constraint count, q perturbations (n), v (n), op, var, t, args ----
def chain(nn, op, var, args=b"", flags=0, spare=1, q=None, n=None):
    nodes = b""
    for i in range(nn):
        nodes += B(0) + M(0.3) + (M(0) if i == 0 else b"") + M(0) + M(0)
    n = n or 4 * nn
    qb = Ms(*(q or (0,) * n))
    return B(flags, nn - 2, spare) + nodes + B(0) + qb + Ms(*(0.1,) * n) + B(op, var) + M(0) + args


seed("chain", "known_pnode_nn", chain(3, 0, 0, B(1)))
seed("chain", "known_pnode_minus1", chain(3, 0, 0, B(0)))
seed("chain", "known_gather_nn_minus_1", chain(3, 1, 0, B(1)))
seed("chain", "known_insert_int_max", chain(3, 2, 0, B(4) + M(0)))
seed("chain", "known_gather_v_null_ve", chain(3, 1, 1, B(9, 0)))
seed("chain", "known_force_jac_d_null", chain(3, 8, 2))
seed("chain", "known_energy_nan_q_writes_E", chain(3, 5, 0, flags=1, q=[float("nan")] + [0] * 11))
seed("chain", "good_pnode_valid", chain(3, 0, 0, B(9, 1)))
seed("chain", "good_insert_middle", chain(3, 2, 0, B(9, 0) + M(0)))
seed("chain", "good_energy", chain(4, 5, 0))
seed("chain", "good_length", chain(3, 6, 0))


# -- step: flags, ne - 2, Le (moderate), integrator byte, HHT: rho_inf or
# 4 raw parameters, newton_max, max_halvings + 1, t0, q perturbations,
# rates, h.  BDF: max_order - 1, t0, q, v, t_stop ------------------------
def step(integ, params, t0, Le=0.9, ne=2, flags=0, tail=b""):
    return B(flags, ne - 2) + M(Le - 0.1) + B(integ) + params + B(10, 1) + M(t0) + tail


seed("step", "known_hht_init_t0_nan", step(0, M(0.8), float("nan"), flags=1))
seed("step", "known_hht_init_gamma_nan", step(2, Rs(-0.2, 0.1, 0.3, float("nan")), 0, flags=1))
# element length = the largest real (an fz_real extreme): the consistent
# acceleration's matrix is singular
seed("step", "known_hht_init_writes_state_on_failure",
     B(0, 1) + bytes.fromhex("2ff600008a0a") + B(0) + M(0.8) + B(10, 1) + M(0))
seed("step", "good_hht_step", step(0, M(0.8), 0))
seed("step", "good_hht_step_3el", step(0, M(0.5), 1.0, ne=3))
seed("step", "good_bdf_step", B(0, 0) + M(0.8) + B(1, 1) + M(0))


def main():
    for h, lst in SEEDS.items():
        d = os.path.join(ROOT, h)
        os.makedirs(d, exist_ok=True)
        for name, data in lst:
            with open(os.path.join(d, name), "wb") as f:
                f.write(data)


if __name__ == "__main__":
    main()
