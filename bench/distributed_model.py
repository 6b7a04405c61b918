#!/usr/bin/python3
"""The cost model of a distributed run (docs/distributed.md "Cost model"), fitted to the measurements
of bench/run_distributed_scaling.sh, and its projection to a 256^3 cubic B-spline USL case on 16, 128 and 1000 cores.

    /usr/bin/python3 bench/distributed_model.py build/distributed_scaling.csv [--latency-us A --bandwidth-gbs B]

Model of the stepping time of one rank holding N_r particles on T threads (USL, one scatter per step):

    t = c_p N_r [ f_s / min(T, k_r) + (1 - f_s) / T ] / e_T      compute: particle-updates, the scatter share f_s
                                                                   limited to k_r concurrent scatters (slabs or
                                                                   tiles of one colour on the rank)
      + w c_p N_r / T                                            waiting at the colour rounds and the step's
                                                                   reduction (unequal loads or cores; w fitted at
                                                                   2 ranks: halo beyond the transfer + other_max
                                                                   - other_min)
      + n_rounds alpha + bytes_r / beta                          halo: colour rounds x latency + bytes / bandwidth
      + c_m N_r / T                                              migration: scanning the owners of the particles

c_p (s per particle-update, 1 rank x 1 thread), f_s (the P2G share), e_T (thread efficiency, from 1 x 2), c_m and w
(from 2 x 1) are fitted; alpha and beta are the ping-pong's (shared memory) or an assumed interconnect's.
Parallel efficiency on P cores: E = t(1 core) / (P t(P cores)).
"""
import argparse
import csv
import math
import statistics
import sys

import numpy as np

# Assumed interconnect (not measured here): an InfiniBand HDR-class link, MPI one-way latency and bandwidth.
IB_LATENCY = 1.5e-6  # s
IB_BANDWIDTH = 12e9  # B/s
# Threads per rank the projection tries: at most 16 (a socket; one rank's threads share its memory); the
# "slabs of tiles" rows (the engine since session 12) also try a whole 64-core node per rank (THREADS_NODE).
THREADS = [1, 2, 4, 8, 16]
THREADS_NODE = THREADS + [32, 38, 64]


def load(path):
    rows = list(csv.DictReader(open(path)))
    for r in rows:
        for k in r:
            if k != "case":
                r[k] = float(r[k])
    return rows


def median_row(rows, case, ranks, threads):
    """The run of median wall time (its phases with it) and the loads of all runs."""
    sel = [r for r in rows if r["case"] == case and r["ranks"] == ranks and r["threads"] == threads]
    if not sel:
        return None
    sel.sort(key=lambda r: r["wall"])
    m = dict(sel[len(sel) // 2])
    m["loads"] = [r["load"] for r in sel]
    m["walls"] = [r["wall"] for r in sel]
    return m


def compute_spread(m):
    """How much longer the slowest rank computed than the fastest (P2G + grid + G2P + stress): with equal particle
    counts, the cores' unequal speed (a shared machine) or an unequal load; '-' for one rank or an older CSV."""
    lo, hi = m.get("compute_min", 0.0), m.get("compute_max", 0.0)
    return f"{hi / lo - 1:.1%}" if m["ranks"] != 1 and lo > 0 else "-"


def paired(rows, case, ranks, threads):
    """The median over the rounds (the CSV's run column) of the round's 1 x 1 wall time over this configuration's (weak:
    the efficiency); '-' for 1 x 1 or without a common round. The script runs every configuration once per round,
    so a pair saw the same machine."""
    if (ranks, threads) == (1, 1):
        return "-"
    base = case.replace("_baseline", "")
    one = {r["run"]: r["wall"] for r in rows if r["case"] == base and r["ranks"] == 1 and r["threads"] == 1}
    ratios = sorted(one[r["run"]] / r["wall"] for r in rows
                    if r["case"] == case and r["ranks"] == ranks and r["threads"] == threads and r["run"] in one)
    if not ratios:
        return "-"
    suffix = "" if case.startswith("weak") else "x"
    return f"{statistics.median(ratios):.2f}{suffix} ({', '.join(f'{q:.2f}' for q in ratios)})"


def of_the_control(rows, case):
    """Per round, the machine's control wall (two independent 1-rank runs of half the scene at once, the slower's)
    over the 2 x 1 run's: the share of what this machine allowed at that moment that the decomposition reached; the
    median and the rounds, or None without control rows."""
    control = {r["run"]: r["wall"] for r in rows if r["case"] == case and r["ranks"] == 0}
    ratios = sorted(control[r["run"]] / r["wall"] for r in rows
                    if r["case"] == case and r["ranks"] == 2 and r["threads"] == 1 and r["run"] in control)
    return (statistics.median(ratios), ratios) if ratios else None


def other_range(m):
    lo, hi = m.get("other_min", m["other"]), m.get("other_max", m["other"])
    return f"{m['other']:.3f}" if m["ranks"] == 1 or hi == lo else f"{lo:.3f}-{hi:.3f}"


def table(rows):
    out = ["| case | ranks x threads | particles | wall (median) | runs | load | updates/s | speed-up | paired | P2G | grid | "
           "G2P | stress | halo (max) | migrate (max) | rebalance | sort | other (min-max) | compute spread |",
           "|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|---|"]
    for case in ["strong2d", "strong2d_baseline", "strong3d", "strong3d_baseline", "weak", "weak_baseline"]:
        base = median_row(rows, case.replace("_baseline", ""), 1, 1) if case.endswith("_baseline") else None
        for ranks, threads in [(1, 1), (1, 2), (2, 1), (0, 1)]:
            m = median_row(rows, case, ranks, threads)
            if not m:
                continue
            rate = m["particles"] * m["steps"] / m["wall"]
            if base is None:
                base = m
            if case.startswith("weak"):
                speed = base["wall"] / m["wall"]  # weak: the efficiency t(1) / t(R)
                label = f"{speed:.2f} (eff.)"
            else:
                label = f"{base['wall'] / m['wall']:.2f}x"
            shape = "control: 2 x 1 runs of half, no MPI" if ranks == 0 else f"{ranks:.0f} x {threads:.0f}"
            out.append(
                f"| {case} | {shape} | {m['particles']:.0f} | {m['wall']:.3f} s | "
                f"{', '.join(f'{w:.2f}' for w in sorted(m['walls']))} | "
                f"{min(m['loads']):.1f}-{max(m['loads']):.1f} | {rate:.3g} | {label} | "
                f"{paired(rows, case, ranks, threads)} | {m['p2g']:.3f} | "
                f"{m['grid']:.3f} | {m['g2p']:.3f} | {m['stress']:.3f} | {m['halo']:.3f} ({m['halo_max']:.3f}) | "
                f"{m['migrate']:.3f} ({m['migrate_max']:.3f}) | {m['rebalance']:.3f} | {m.get('sort', 0.0):.3f} | "
                f"{other_range(m)} | "
                f"{compute_spread(m)} |")
    return "\n".join(out)


def fit(rows, case, bytes_per_message):
    """Constants of one scene: c_p, f_s, e_2, w, c_m, rebalance per check."""
    one, two_t, two_r = (median_row(rows, case, 1, 1), median_row(rows, case, 1, 2), median_row(rows, case, 2, 1))
    updates = one["particles"] * one["steps"]
    f = {"c_p": one["wall"] / updates, "f_s": one["p2g"] / one["wall"]}
    f["e_2"] = one["wall"] / (2 * two_t["wall"]) if two_t else float("nan")
    if two_r:
        updates_r = two_r["particles"] / 2 * two_r["steps"]  # per rank
        exchanges = 2 * two_r["steps"]  # USL: one scatter, two colour rounds, one exchange call after each
        transfer = exchanges / 2 * (ALPHA + bytes_per_message / BETA)  # a rank sends in one of the two rounds
        f["halo_measured"] = two_r["halo_max"]
        f["halo_transfer"] = transfer
        # The waiting: in the exchanges beyond the transfer, and at the step's reduction, where the faster rank's
        # "other" exceeds the slower's (other_max - other_min; 0 in an older CSV without the ranks' spread).
        f["reduce_wait"] = two_r.get("other_max", 0.0) - two_r.get("other_min", 0.0)
        f["compute_spread"] = compute_spread(two_r)
        f["w"] = (max(0.0, two_r["halo_max"] - transfer) + f["reduce_wait"]) / (f["c_p"] * updates_r)
        # The same per round: a shared machine only adds waiting (a slower core makes the other rank wait; the
        # faster rank's compute stays put), so the least disturbed round is the estimate of the decomposition's own
        # imbalance, and the median round's says what this machine adds.
        per_round = sorted((max(0.0, r["halo_max"] - transfer) + r.get("other_max", 0.0) - r.get("other_min", 0.0)) /
                           (f["c_p"] * updates_r) for r in rows
                           if r["case"] == case and r["ranks"] == 2 and r["threads"] == 1)
        f["w_rounds"] = per_round
        f["w_least"] = per_round[0] if per_round else f["w"]
        f["c_m"] = two_r["migrate_max"] / updates_r
        f["rebalance"] = two_r["rebalance"]
        f["speedup_2r"] = one["wall"] / two_r["wall"]
        f["share_2r"] = (two_r["halo_max"] + two_r["migrate_max"]) / two_r["wall"]
    return f


def step_time(P, T, decomposition, c, alpha, beta, n_axis=256, ppc=8, e_T=1.0):
    """Projected stepping time per step of the 256^3 cubic B-spline USL case on P cores, T threads per rank; a
    decomposition that has fewer units (slabs, tiles) than P / T ranks leaves the other cores idle."""
    N = n_axis**3 * ppc
    R = P // T
    if R < 1:
        return None
    if decomposition in ("slabs", "slabs of tiles"):
        R = min(R, math.ceil(n_axis / 5))
    Nr = N / R
    reach = 5  # cubic B-spline: a slab or tile's particles reach 2 node layers below, 3 above
    bytes_per_node = 56  # mass, momentum, force: 7 doubles in 3D
    if decomposition == "slabs":
        slabs = math.ceil(n_axis / 5)  # slab_cells = 5
        k = math.ceil(slabs / R / 2)  # slabs of one colour on a rank
        rounds = 2
        message = reach * (n_axis + 1) ** 2 * bytes_per_node
        halo = rounds * (alpha + message / beta) if R > 1 else 0  # one message per round (send or receive)
    elif decomposition == "slabs of tiles":
        # Ranks own slabs as above; the threads scatter the slab's tiles (8 cells wide, 2^3 colours, the slab
        # parity first): k_r = the rank's slabs of a colour x the tiles of a colour in a slab. A rank holding one
        # slab scatters in one of the two slab rounds and waits for its neighbours in the other: its scatter takes
        # twice its own time.
        slabs = math.ceil(n_axis / 5)
        per_slab = (math.ceil(n_axis / 8) // 2) ** 2
        k = math.ceil(slabs / R / 2) * per_slab
        rounds = 2
        message = reach * (n_axis + 1) ** 2 * bytes_per_node
        halo = rounds * (alpha + message / beta) if R > 1 else 0
        if slabs / R < 2:
            c = dict(c, f_s=2 * c["f_s"])  # the scatter share, serialised over the two slab rounds
    else:  # 3D blocks of 8^3-cell tiles, 2^3 colours, a rank owns a cube of tiles
        tiles = (n_axis // 8) ** 3
        if R > tiles:
            return None
        k = max(1, tiles // R // 8)
        side = n_axis / round(R ** (1 / 3)) if R > 1 else n_axis
        rounds = 8
        sent = 6 * (side + reach) ** 2 * reach * bytes_per_node  # every face's overlap, once each way
        halo = rounds * alpha + sent / beta if R > 1 else 0
    eT = e_T if T > 1 else 1.0
    compute = c["c_p"] * Nr * (c["f_s"] / min(T, k) + (1 - c["f_s"]) / T) / eT
    wait = c["w"] * c["c_p"] * Nr / T if R > 1 else 0
    migrate = c["c_m"] * Nr / T if R > 1 else 0
    return compute + wait + halo + migrate, compute, wait, halo, migrate, R, T


def project(c, alpha, beta, label):
    N = 256**3 * 8
    t1 = c["c_p"] * N
    lines = [f"projection, 256^3 cells x 8 particles ({N:.3g}) cubic B-spline USL, {label}: "
             f"latency {alpha * 1e6:.2f} us, bandwidth {beta / 1e9:.2f} GB/s",
             "| cores | decomposition | best ranks x threads | step (ms) | compute | wait | halo | migrate | "
             "efficiency |", "|---|---|---|---|---|---|---|---|---|"]
    for P in [16, 128, 1000]:
        for dec in ["slabs", "slabs of tiles", "blocks"]:
            best = None
            for T in (THREADS_NODE if dec == "slabs of tiles" else THREADS):
                r = step_time(P, T, dec, c, alpha, beta)
                if r and (best is None or r[0] < best[0]):
                    best = r
            t, comp, wait, halo, mig, R, T = best
            idle = f" ({P - R * T} idle)" if R * T < P else ""
            lines.append(f"| {P} | {dec} | {R} x {T}{idle} | {1e3 * t:.2f} | {1e3 * comp:.2f} | {1e3 * wait:.2f} | "
                         f"{1e3 * halo:.3f} | {1e3 * mig:.2f} | {t1 / (P * t):.1%} |")
    return "\n".join(lines)


def main():
    global ALPHA, BETA
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("csv")
    ap.add_argument("--latency-us", type=float, default=IB_LATENCY * 1e6, help="assumed interconnect latency")
    ap.add_argument("--bandwidth-gbs", type=float, default=IB_BANDWIDTH / 1e9, help="assumed bandwidth, GB/s")
    a = ap.parse_args()
    rows = load(a.csv)
    pp = [r for r in rows if r["case"] == "pingpong"]
    if pp:  # the pingpong rows carry latency (us) in p2g and bandwidth (MB/s) in grid
        ALPHA = statistics.median(r["p2g"] for r in pp) * 1e-6
        BETA = statistics.median(r["grid"] for r in pp) * 1e6
        print(f"link (ping-pong, shared memory, {len(pp)} runs, load {min(r['load'] for r in pp):.1f}-"
              f"{max(r['load'] for r in pp):.1f}): latency {ALPHA * 1e6:.2f} us "
              f"({', '.join('%.2f' % r['p2g'] for r in pp)}), bandwidth {BETA / 1e9:.2f} GB/s "
              f"({', '.join('%.2f' % (r['grid'] / 1e3) for r in pp)})")
    else:
        ALPHA, BETA = 0.5e-6, 5e9
        print("link: no ping-pong rows; assumed 0.5 us, 5 GB/s")
    print()
    print(table(rows))
    print()
    consts = {}
    for case in ["strong2d", "strong3d"]:
        one = median_row(rows, case, 1, 1)
        if not one:
            continue
        # The message of the script's scenes: one node layer of 1000 + 1 nodes (2D hats, 40 B a node) at 1,005,304
        # particles, five layers of (77 + 1)^2 nodes (3D cubic, 56 B) at 244,698; --quick scenes scale by the count.
        if case == "strong2d":
            cells = round(1000 * math.sqrt(one["particles"] / 1005304))
            message = 1 * (cells + 1) * 40
        else:
            cells = round(77 * (one["particles"] / 244698) ** (1 / 3))
            message = 5 * (cells + 1) ** 2 * 56
        c = fit(rows, case, message)
        consts[case] = c
        s = (f"fit {case}: c_p = {c['c_p'] * 1e9:.1f} ns per particle-update (1 x 1), P2G share f_s = {c['f_s']:.2f}"
             f", 2-thread efficiency e_2 = {c['e_2']:.2f}")
        if "w" in c:
            s += (f"; 2 ranks: speed-up {c['speedup_2r']:.2f}x, halo {c['halo_measured']:.3f} s of which transfer "
                  f"(rounds x latency + bytes / bandwidth) {c['halo_transfer'] * 1e3:.2f} ms, waiting w = "
                  f"{c['w']:.3f} of compute in the median run (of which waiting at the step's reduction "
                  f"{c['reduce_wait']:.3f} s; the ranks' compute differed by {c['compute_spread']}), per round "
                  f"{', '.join(f'{w:.3f}' for w in c['w_rounds'])}, least {c['w_least']:.3f}; migration c_m = {c['c_m'] * 1e9:.2f} ns per particle-update; "
                  f"halo + migration {c['share_2r']:.1%} of the step; rebalance checks {c['rebalance']:.4f} s")
        control = of_the_control(rows, case)
        if control:
            ceiling = paired(rows, case, 0, 1)
            s += (f"; the machine's control (two independent half runs at once) allowed a paired {ceiling}, of which "
                  f"the 2 x 1 run reached {control[0]:.1%} ({', '.join(f'{q:.1%}' for q in control[1])})")
        print(s)
    weak1, weak2 = median_row(rows, "weak", 1, 1), median_row(rows, "weak", 2, 1)
    if weak1 and weak2:
        print(f"weak scaling, {weak1['particles']:.0f} -> {weak2['particles']:.0f} particles on 1 -> 2 ranks: "
              f"efficiency {weak1['wall'] / weak2['wall']:.2f}")
    if "strong3d" in consts:
        c = dict(consts["strong3d"])
        if "w" not in c:
            c.update(w=0.0, c_m=0.0)
        print()
        print(project(c, ALPHA, BETA, "measured shared-memory link"))
        print()
        print(project(c, a.latency_us * 1e-6, a.bandwidth_gbs * 1e9,
                      "ASSUMED InfiniBand-class link (not measured)"))
        if "w_least" in c:
            print()
            print(project(dict(c, w=c["w_least"]), a.latency_us * 1e-6, a.bandwidth_gbs * 1e9,
                          f"ASSUMED InfiniBand-class link, the least disturbed round's waiting (w = {c['w_least']:.3f})"))
        c0 = dict(c, w=0.0)
        print()
        print(project(c0, a.latency_us * 1e-6, a.bandwidth_gbs * 1e9,
                      "ASSUMED InfiniBand-class link, no waiting (w = 0: perfectly balanced colour rounds)"))


if __name__ == "__main__":
    sys.exit(main())
