#!/usr/bin/env python3
"""Writes core/texture/pov_noise_tables.h: the tables POV-Ray 3.7's noise reads.

  tests/pov/noise_tables.py [--povray povray] [--out core/texture/pov_noise_tables.h]

- The lattice hash (4096 entries) and the tables of noise_generator 3 (2048 permutation entries
  and 2048 gradients) come from POV-Ray's documented generator, the C library's classic linear
  congruential step `r = r * 1812433253 + 12345` on 32 bits, whose bits 16..30 are the draw; they
  are computed here. So are the cells and crackle patterns' random numbers, the Mersenne
  Twister's draws from its default seed.
- The 267 random values that noise_generator 1 and 2 and the vector noise (DNoise) weight are
  measured from POV-Ray itself: `vturbulence(L, O, 1, P)` is one octave of the vector noise. At
  a lattice point each component is half of one value; just beside a lattice point the
  components' slopes are the values that follow. The script renders one 1x1 image whose scene
  writes those probes to a file, solves for the values, rounds them to the six significant
  digits POV-Ray keeps, and checks that the rounded values give back every probe.
"""
import argparse
import os
import subprocess
import sys
import tempfile

MASK32 = 0xFFFFFFFF


def lcg(state):
    state = (state * 1812433253 + 12345) & MASK32
    return state, (state >> 16) & 0x7FFF


def hash_table():
    t = list(range(4096))
    s = 0
    for i in range(4095, -1, -1):
        s, r = lcg(s)
        j = r % 4096
        t[i], t[j] = t[j], t[i]
    return t + t


def solid_tables():
    n = 2048
    s = 1
    grads = []
    for _ in range(n):
        while True:
            v = []
            for _ in range(3):
                s, r = lcg(s)
                v.append(r % (2 * n) - n)
            q = sum((c / n) ** 2 for c in v)
            if 1e-5 <= q <= 1.0:
                break
        grads.append(v)
    perm = list(range(n)) + [0] * (n + 2)
    for i in range(n, 0, -2):
        k = perm[i]
        s, r = lcg(s)
        j = r % n
        perm[i] = perm[j]
        perm[j] = k
    for i in range(n + 2):
        perm[n + i] = perm[i]
    return perm[:n], grads


def mt19937(seed, count):
    """The first `count` outputs of the Mersenne Twister MT19937 seeded with init_genrand(seed)
    (the C++ and Boost engines' default seed is 5489)."""
    n, m = 624, 397
    mt = [0] * n
    mt[0] = seed & MASK32
    for i in range(1, n):
        mt[i] = (1812433253 * (mt[i - 1] ^ (mt[i - 1] >> 30)) + i) & MASK32
    out, idx = [], n
    while len(out) < count:
        if idx >= n:
            for i in range(n):
                y = (mt[i] & 0x80000000) | (mt[(i + 1) % n] & 0x7FFFFFFF)
                mt[i] = mt[(i + m) % n] ^ (y >> 1) ^ (0x9908B0DF if y & 1 else 0)
            idx = 0
        y = mt[idx]
        idx += 1
        y ^= y >> 11
        y ^= (y << 7) & 0x9D2C5680
        y ^= (y << 15) & 0xEFC60000
        y ^= y >> 18
        out.append(y)
    return out


NOISE_MIN = -10000


def lattice(v):  # a whole coordinate's hash index
    return (v - NOISE_MIN) & 0xFFF


def slot(H, x, y, z):
    """The value index (0..255) whose triple a lattice point's noise starts at."""
    return H[H[H[lattice(x)] ^ lattice(y)] ^ lattice(z)] & 0xFF


def probe_points(H):
    """Lattice points covering every slot, each with probes beside it along x, y and z."""
    first = {}
    for x in range(64):
        for y in range(64):
            for z in range(8):
                first.setdefault(slot(H, x, y, z), (x, y, z))
        if len(first) == 256:
            break
    assert len(first) == 256
    return first


def write_line(values):
    """A scene line writing `values` (expressions) to the probe file, 17 decimals each."""
    return ('#write(F, ' + ', " ", '.join('str(%s, 0, 17)' % v for v in values) +
            ', "\\n")')


def povray_rows(povray, body):
    """Renders a 1x1 image of a scene whose lines `body` write rows to the probe file F, and
    returns the rows, each a list of words."""
    lines = ['#version 3.7;', 'global_settings { assumed_gamma 1 }',
             'camera { location <0, 0, -1> look_at 0 }', '#fopen F "probes.txt" write']
    lines += body + ['#fclose F']
    with tempfile.TemporaryDirectory() as d:
        with open(os.path.join(d, 'probe.pov'), 'w') as f:
            f.write('\n'.join(lines) + '\n')
        subprocess.run([povray, '+Iprobe.pov', '+W1', '+H1', '-D', '-GA', '+O-', '-F'],
                       cwd=d, check=True, stdout=subprocess.DEVNULL, stderr=subprocess.DEVNULL)
        with open(os.path.join(d, 'probes.txt')) as f:
            return [line.split() for line in f if line.strip()]


def run_povray(povray, points):
    # Each probe: the point, then the vector noise's three components there.
    lines = []
    for p in points:
        lines.append('#declare V = vturbulence(2, 0.5, 1, <%r, %r, %r>);' % p)
        lines.append(write_line(['V.x', 'V.y', 'V.z']))
    return [tuple(float(t) for t in row) for row in povray_rows(povray, lines)]


def scurve(t):
    return t * t * (3.0 - 2.0 * t)


def measure_rtable(povray, H):
    first = probe_points(H)
    # At lattice point of slot j the components are R[j]/2, R[j+4]/2, R[j+8]/2. Beside it,
    # at offset d along axis a, component c is
    #   (1 - s) (R[j+4c]/2 + R[j+4c+1+a] d) + s (R'[..]/2 + R'[..+1+a] (d - 1)),  s = scurve(d),
    # where the primed values belong to the neighbouring lattice point's slot.
    ds = (0.25, 0.5)
    points, keys = [], []
    for j, (x, y, z) in sorted(first.items()):
        base = (x, y, z)
        points.append(tuple(float(c) for c in base))
        keys.append((j, base, None, 0))
        for a in range(3):
            nb = list(base)
            nb[a] += 1
            points.append(tuple(float(c) for c in nb))
            keys.append((j, base, a, 1))
            for d in ds:
                p = [float(c) for c in base]
                p[a] += d
                points.append(tuple(p))
                keys.append((j, base, a, d))
    values = run_povray(povray, points)
    assert len(values) == len(points), (len(values), len(points))
    got = dict(zip([(k[1], k[2], k[3]) for k in keys], values))
    R = {}
    for j, base in sorted(first.items()):
        lat = got[(base, None, 0)]
        for c in range(3):
            R.setdefault(j + 4 * c, 2 * lat[c])
        for a in range(3):
            nb = got[(base, a, 1)]
            (p1, p2) = (got[(base, a, d)] for d in ds)
            for c in range(3):
                A, A2 = lat[c] , nb[c]
                # f(d) = (1 - s)(A + B d) + s (A2 + B2 (d - 1)): two probes, two unknowns.
                rows = []
                for d, f in zip(ds, (p1[c], p2[c])):
                    s = scurve(d)
                    rows.append(((1 - s) * d, s * (d - 1), f - (1 - s) * A - s * A2))
                (a1, b1, c1), (a2, b2, c2) = rows
                det = a1 * b2 - a2 * b1
                B = (c1 * b2 - c2 * b1) / det
                R.setdefault(j + 4 * c + 1 + a, B)
    assert sorted(R) == list(range(267)), 'slots not covered: %s' % (set(range(267)) - set(R))
    table = [float('%.6g' % R[k]) for k in range(267)]
    worst = max(abs(table[k] - R[k]) for k in range(267))
    assert worst < 1e-9, 'measured values are not six-digit decimals (off by %g)' % worst
    return table


def print_golden(povray):
    """POV-Ray's noise under generators 1, 2, 3 (f_noise_generator), its vector noise and a
    six-octave vector turbulence at test points, as rows for core/texture/pov_noise_test.cpp."""
    import random
    rng = random.Random(7)
    pts = [(0.5, 0.25, 0.125), (-0.5, -1.75, 2.0), (3.0, 4.0, -5.0), (1e-11, -1e-11, 0.0),
           (-2.00000000001, 7.3, 1.1), (1234.567, -8901.234, 42.0)]
    pts += [tuple(round(rng.uniform(-40, 40), 6) for _ in range(3)) for _ in range(14)]
    lines = ['#include "functions.inc"']
    for p in pts:
        lines.append('#declare P = <%r, %r, %r>;' % p)
        lines.append('#declare D = vturbulence(2, 0.5, 1, P);')
        lines.append('#declare T = vturbulence(2.1, 0.45, 6, P);')
        vals = ['f_noise_generator(P.x, P.y, P.z, %d)' % g for g in (1, 2, 3)]
        vals += ['D.x', 'D.y', 'D.z', 'T.x', 'T.y', 'T.z']
        lines.append(write_line(vals))
    rows = povray_rows(povray, lines)
    for p, r in zip(pts, rows):
        print('    {{%r, %r, %r}, {%s}},' % (p + (', '.join(r),)))


def c_list(values, per_line, fmt):
    out = []
    for i in range(0, len(values), per_line):
        last = i + per_line >= len(values)
        out.append('    ' + ', '.join(fmt(v) for v in values[i:i + per_line]) +
                   ('' if last else ', \\'))
    return '\n'.join(out)


def main():
    ap = argparse.ArgumentParser(description=__doc__.split('\n')[0])
    ap.add_argument('--povray', default='povray')
    here = os.path.dirname(os.path.abspath(__file__))
    ap.add_argument('--out', default=os.path.join(here, '..', '..', 'core', 'texture',
                                                  'pov_noise_tables.h'))
    ap.add_argument('--golden', action='store_true',
                    help="print POV-Ray's noises at test points as C++ rows instead")
    args = ap.parse_args()
    if args.golden:
        return print_golden(args.povray)
    H = hash_table()
    perm, grads = solid_tables()
    R = measure_rtable(args.povray, H)
    text = f'''// Generated by tests/pov/noise_tables.py: do not edit. The tables POV-Ray 3.7's noise reads,
// as lists for core/texture/pov_noise.h to define on the host and the device. The lattice hash
// and generator 3's tables follow POV-Ray's generator; the 267 values were measured from
// POV-Ray 3.7 by the script's probes.
#pragma once
// clang-format off

// The lattice hash: a permutation of 0..4095 (read modulo 4096).
#define SHEAF_POV_NOISE_HASH \\
{c_list(H[:4096], 16, str)}

// The random values generators 1 and 2 and the vector noise weight (267, each in [-1, 1]).
#define SHEAF_POV_NOISE_VALUES \\
{c_list(R, 6, repr)}

// Generator 3 (Perlin's): the permutation of 0..2047 (read modulo 2048) ...
#define SHEAF_POV_NOISE_SOLID_PERM \\
{c_list(perm, 16, str)}

// ... and the gradients' numerators over 2048, normalised where they are read.
#define SHEAF_POV_NOISE_SOLID_GRAD \\
{c_list([c for g in grads for c in g], 15, str)}

// The random numbers of the cells and crackle patterns: MT19937's first 4098 draws from its
// default seed, each over 2^32 - 1 (the lattice hash reaches no further).
#define SHEAF_POV_PATTERN_RANDS \\
{c_list(mt19937(5489, 4098), 8, str)}
// clang-format on
'''
    with open(args.out, 'w') as f:
        f.write(text)
    print('wrote', os.path.normpath(args.out))


if __name__ == '__main__':
    sys.exit(main())
