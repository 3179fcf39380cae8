#!/usr/bin/env python3
"""Generates skyig's truncated VSOP87B and ELP 2000-82B series (vsop87b_truncated.inc,
elp82b_truncated.inc) from a full transcription of both theories, and measures the error the
truncation adds (full versus truncated series, 1900-2100).

Input: the source tree of libnova 0.16 (Debian source package `libnova`, `apt-get source
libnova`), whose src/{mercury,venus,earth,mars,jupiter,saturn}.c hold the complete VSOP87B
series (Bretagnon & Francou 1988, heliocentric spherical L, B, R, J2000 ecliptic) and whose
src/lunar.c holds all 36 files of ELP 2000-82B (Chapront-Touze & Chapront 1983/1988, VizieR
VI/79). Only the numbers are taken; skyig's evaluation code is its own.

Usage: generate_series.py LIBNOVA_SRC_DIR OUT_DIR [--check]
"""
import math, random, re, sys

# ---------------------------------------------------------------- VSOP87B
VSOP_BODIES = ['earth', 'mercury', 'venus', 'mars', 'jupiter', 'saturn']
# Keep a term when |A| * Tmax^k (R terms: divided by the mean distance) >= threshold (rad).
VSOP_THRESHOLD = {'earth': 1e-8, 'mercury': 3e-7, 'venus': 1e-7, 'mars': 1e-7,
                  'jupiter': 3e-7, 'saturn': 3e-7}
VSOP_RMEAN = {'earth': 1.0, 'mercury': 0.387, 'venus': 0.723, 'mars': 1.524,
              'jupiter': 5.203, 'saturn': 9.537}
TMAX_MILLENNIA = 0.1  # 1900-2100
COORD = {'longitude_l': 0, 'latitude_b': 1, 'radius_r': 2}
NUM = r'([-0-9.eE+]+)'


def parse_vsop(path, body):
    text = open(path).read()
    terms = []
    for m in re.finditer(r'%s_(longitude_l|latitude_b|radius_r)(\d)\s*\[[A-Z_0-9]+\]\s*=\s*\{(.*?)\};' % body, text, re.S):
        coord, k = COORD[m.group(1)], int(m.group(2))
        for t in re.finditer(r'\{\s*' + NUM + r'\s*,\s*' + NUM + r'\s*,\s*' + NUM + r'\s*\}', m.group(3)):
            terms.append((coord, k, float(t.group(1)), float(t.group(2)), float(t.group(3))))
    return terms


def keep_vsop(body, term):
    coord, k, a = term[0], term[1], term[2]
    eff = abs(a) * TMAX_MILLENNIA ** k / (VSOP_RMEAN[body] if coord == 2 else 1.0)
    return eff >= VSOP_THRESHOLD[body]


# ---------------------------------------------------------------- ELP 2000-82B
RAD = 648000.0 / math.pi
DEG = math.pi / 180.0
AM = 0.074801329518
ALPHA = 0.002571881335
DTASM = 2.0 * ALPHA / (3.0 * AM)
W12 = 1732559343.73604 / RAD
PRECES = 5029.0966 / RAD
# Corrections of the constants fitted to DE200/LE200 (ELP 2000-82B notice).
DELNU = (0.55604 / RAD) / W12
DELE = 0.01789 / RAD
DELG = -0.08066 / RAD
DELNP = (-0.06424 / RAD) / W12
DELEP = -0.12879 / RAD
# Delaunay arguments D, l', l, F (rad, t in Julian centuries TDB from J2000).
DEL = [[5.198466741027443, 7771.377146811758394, -0.000028449351621, 0.000000031973462, -0.000000000154365],
       [-0.043125180208125, 628.301955168488007, -0.000002680534843, 0.000000000712676, 0.000000000000727],
       [2.355555898265799, 8328.691426955554562, 0.000157027757616, 0.000000250411114, -0.000000001186339],
       [1.627905233371468, 8433.466158130539043, -0.000059392100004, -0.000000004949948, 0.000000000020217]]
ZETA = [(218.0 + 18.0 / 60.0 + 59.95571 / 3600.0) * DEG, 1732559343.73604 / RAD + PRECES]
# Mean longitudes of Mercury..Neptune (rad, rad/century).
PLA = [[(252 + 15 / 60 + 3.25986 / 3600) * DEG, 538101628.68898 / RAD],
       [(181 + 58 / 60 + 47.28305 / 3600) * DEG, 210664136.43355 / RAD],
       [(100 + 27 / 60 + 59.22059 / 3600) * DEG, 129597742.2758 / RAD],
       [(355 + 25 / 60 + 59.78866 / 3600) * DEG, 68905077.59284 / RAD],
       [(34 + 21 / 60 + 5.34212 / 3600) * DEG, 10925660.42861 / RAD],
       [(50 + 4 / 60 + 38.89694 / 3600) * DEG, 4399609.65932 / RAD],
       [(314 + 3 / 60 + 18.01841 / 3600) * DEG, 1542481.19393 / RAD],
       [(304 + 20 / 60 + 55.19575 / 3600) * DEG, 786550.32074 / RAD]]
# Keep a term when |A| >= threshold: arcsec for longitude/latitude, km for distance.
ELP_THRESHOLD = [0.01, 0.01, 0.05]


def elp_array(text, name):
    m = re.search(name + r'\s*\[ELP\d+_SIZE\]\s*=\s*\{(.*?)\n\};', text, re.S)
    if not m:
        raise SystemExit('lunar.c: array %s not found' % name)
    return m.group(1)


# Fundamental arguments of the generated table, in this order: Delaunay D, l', l, F with their
# full quartic polynomials (main problem), the same four truncated to linear (perturbations), the
# moon's mean longitude zeta, and the mean longitudes of Mercury..Neptune.
def fundamental_polynomials():
    polys = [list(DEL[i]) for i in range(4)]
    polys += [[DEL[i][0], DEL[i][1], 0.0, 0.0, 0.0] for i in range(4)]
    polys.append([ZETA[0], ZETA[1], 0.0, 0.0, 0.0])
    polys += [[PLA[i][0], PLA[i][1], 0.0, 0.0, 0.0] for i in range(8)]
    return polys


def with_argument(coord, power, a, phase, mult):
    """Term tuple: (coord, power, A, [c0..c4], phase, multipliers of the 17 fundamental arguments)."""
    polys = fundamental_polynomials()
    c = [phase + sum(m * p[0] for m, p in zip(mult, polys))] + [sum(m * p[k] for m, p in zip(mult, polys)) for k in range(1, 5)]
    return (coord, power, a, c, phase, mult)


def parse_elp(path):
    """Every ELP term; see with_argument. Value: A t^power sin(c0 + c1 t + ... + c4 t^4)."""
    text = open(path).read()
    terms = []
    for s in (1, 2, 3):  # main problem (ELP1-3), arguments with t^0..t^4
        body = elp_array(text, 'main_elp%d' % s)
        for m in re.finditer(r'\{\{\s*([-\d]+),\s*([-\d]+),\s*([-\d]+),\s*([-\d]+)\},\s*' + NUM + r',\s*\{'
                             + r',\s*'.join([NUM] * 5) + r'\}\}', body):
            ilu = [int(m.group(i)) for i in range(1, 5)]
            a = float(m.group(5))
            b = [float(m.group(i)) for i in range(6, 11)]
            if s == 3:
                a -= 2.0 * a * DELNU / 3.0
            tgv = b[0] + DTASM * b[4]
            x = a + tgv * (DELNP - AM * DELNU) + b[1] * DELG + b[2] * DELE + b[3] * DELEP
            mult = ilu + [0] * 13
            terms.append(with_argument(s - 1, 0, x, math.pi / 2 if s == 3 else 0.0, mult))  # distance: cosines
    names = {}
    for s in range(4, 10): names[s] = 'earth_pert_elp'
    for s in range(22, 28): names[s] = 'tidal_effects_elp'
    for s in range(28, 31): names[s] = 'moon_pert_elp'
    for s in range(31, 34): names[s] = 'rel_pert_elp'
    for s in range(34, 37): names[s] = 'plan_sol_pert_elp'
    power = {7: 1, 8: 1, 9: 1, 25: 1, 26: 1, 27: 1, 34: 2, 35: 2, 36: 2}
    for s, nm in names.items():  # arguments linear in t
        body = elp_array(text, nm + '%d' % s)
        for m in re.finditer(r'\{\s*([-\d]+),\s*\{\s*([-\d]+),\s*([-\d]+),\s*([-\d]+),\s*([-\d]+)\},\s*'
                             + NUM + r',\s*' + NUM + r',\s*' + NUM + r'\}', body):
            iz = int(m.group(1))
            ilu = [int(m.group(i)) for i in range(2, 6)]
            phase, a = float(m.group(6)), float(m.group(7))
            mult = [0] * 4 + ilu + [iz] + [0] * 8
            terms.append(with_argument((s - 1) % 3, power.get(s, 0), a, phase * DEG, mult))
    for s in range(10, 22):  # planetary perturbations, tables 1 (10-15) and 2 (16-21)
        body = elp_array(text, 'plan_pert_elp%d' % s)
        for m in re.finditer(r'\{\{' + r',\s*'.join([r'\s*([-\d]+)'] * 11) + r'\},\s*' + NUM + r',\s*'
                             + NUM + r',\s*' + NUM + r'\}', body):
            ip = [int(m.group(i)) for i in range(1, 12)]
            theta, a = float(m.group(12)), float(m.group(13))
            if s <= 15:  # table 1: 8 planets, then D, l, F
                mult = [0] * 4 + [ip[8], 0, ip[9], ip[10]] + [0] + ip[0:8]
            else:  # table 2: 7 planets, then D, l', l, F
                mult = [0] * 4 + ip[7:11] + [0] + ip[0:7] + [0]
            terms.append(with_argument((s - 1) % 3, 1 if s in (13, 14, 15, 19, 20, 21) else 0, a, theta * DEG, mult))
    return terms


def keep_elp(term):
    return abs(term[2]) >= ELP_THRESHOLD[term[0]]


# ---------------------------------------------------------------- checks
def vsop_rect(terms, t):
    s = [0.0, 0.0, 0.0]
    for coord, k, a, b, c in terms:
        s[coord] += a * math.cos(b + c * t) * t ** k
    l, b, r = s
    return (r * math.cos(b) * math.cos(l), r * math.cos(b) * math.sin(l), r * math.sin(b))


def angle_arcsec(u, v):
    d = math.sqrt(sum((x - y) ** 2 for x, y in zip(u, v)))
    return d / math.sqrt(sum(x * x for x in u)) * RAD


def check(vsop_full, elp_full):
    random.seed(1)
    dates = [random.uniform(-1.0, 1.0) for _ in range(200)]  # centuries from J2000
    e_full = vsop_full['earth']
    e_tr = [t for t in e_full if keep_vsop('earth', t)]
    for body in VSOP_BODIES:
        full = vsop_full[body]
        tr = [t for t in full if keep_vsop(body, t)]
        worst = 0.0
        for tc in dates:
            tm = tc / 10.0
            ef, et = vsop_rect(e_full, tm), vsop_rect(e_tr, tm)
            if body == 'earth':
                worst = max(worst, angle_arcsec(ef, et))
                continue
            pf, pt = vsop_rect(full, tm), vsop_rect(tr, tm)
            worst = max(worst, angle_arcsec([p - e for p, e in zip(pf, ef)], [p - e for p, e in zip(pt, et)]))
        print('VSOP87B %-8s %5d of %5d terms, max geocentric direction error %.3f arcsec'
              % (body, len(tr), len(full), worst))
    worst = [0.0, 0.0, 0.0]
    for tc in dates[:60]:
        s_full, s_tr = [0.0] * 3, [0.0] * 3
        for term in elp_full:
            coord, k, a, c = term[:4]
            x = a * tc ** k * math.sin(c[0] + tc * (c[1] + tc * (c[2] + tc * (c[3] + tc * c[4]))))
            s_full[coord] += x
            if keep_elp(term):
                s_tr[coord] += x
        worst = [max(w, abs(f - t)) for w, f, t in zip(worst, s_full, s_tr)]
    n = sum(1 for t in elp_full if keep_elp(t))
    print('ELP2000-82B %d of %d terms, max error longitude %.3f", latitude %.3f", distance %.3f km'
          % (n, len(elp_full), *worst))


def main():
    if len(sys.argv) < 3:
        raise SystemExit(__doc__)
    src, out = sys.argv[1], sys.argv[2]
    vsop = {b: parse_vsop('%s/%s.c' % (src, b), b) for b in VSOP_BODIES}
    with open('%s/vsop87b_truncated.inc' % out, 'w') as f:
        f.write('// Generated by ephemeris/data/generate_series.py: VSOP87B (Bretagnon & Francou 1988),\n'
                '// heliocentric L, B (rad), R (au), J2000 ecliptic, truncated for 1900-2100.\n'
                '// Row: {coordinate 0=L 1=B 2=R, power of T (Julian millennia TDB), A, B, C}: A T^k cos(B + C T).\n')
        for b in VSOP_BODIES:
            kept = [t for t in vsop[b] if keep_vsop(b, t)]
            f.write('// %s: %d of %d terms, threshold %.0e\n' % (b, len(kept), len(vsop[b]), VSOP_THRESHOLD[b]))
            f.write('static constexpr VsopTerm kVsop%s[] = {\n' % b.capitalize())
            for coord, k, a, bb, c in kept:
                f.write('{%d,%d,%.11f,%.11f,%.11f},\n' % (coord, k, a, bb, c))
            f.write('};\n')
    elp = parse_elp('%s/lunar.c' % src)
    kept = [t for t in elp if keep_elp(t)]
    kept.sort(key=lambda t: (t[0], t[1], -abs(t[2])))
    polys = fundamental_polynomials()
    with open('%s/elp82b_truncated.inc' % out, 'w') as f:
        f.write('// Generated by ephemeris/data/generate_series.py: ELP 2000-82B (Chapront-Touze & Chapront),\n'
                '// all 36 series with the DE200/LE200 constant corrections folded into the amplitudes,\n'
                '// %d of %d terms (|A| >= %g arcsec in longitude/latitude, %g km in distance).\n'
                '// Row: {coordinate 0=V 1=U 2=r, power k of t (Julian centuries TDB), A, phase, {n_0..n_16}}:\n'
                '// A t^k sin(phase + sum n_j F_j(t)), A in arcsec (V, U) or km (r), F_j the fundamental\n'
                '// arguments of kElpArguments (D, l\', l, F quartic; D, l\', l, F linear; zeta; Mercury..Neptune).\n'
                % (len(kept), len(elp), ELP_THRESHOLD[0], ELP_THRESHOLD[2]))
        f.write('static constexpr double kElpArguments[17][5] = {\n')
        for p in polys:
            f.write('{%s},\n' % ','.join('%.17g' % v for v in p))
        f.write('};\n')
        f.write('static constexpr ElpTerm kElpTerms[] = {\n')
        for coord, k, a, c, phase, mult in kept:
            f.write('{%d,%d,%.9g,%.17g,{%s}},\n' % (coord, k, a, phase, ','.join(str(m) for m in mult)))
        f.write('};\n')
    if '--check' in sys.argv:
        check(vsop, elp)


if __name__ == '__main__':
    main()
