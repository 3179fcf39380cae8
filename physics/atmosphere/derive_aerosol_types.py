#!/usr/bin/env python3
"""Writes physics/atmosphere/aerosol_type_opac.inc: the aerosol types of OPAC 3.1 (Hess, Koepke
and Schult 1998, "Optical Properties of Aerosols and Clouds: The Software Package OPAC", BAMS 79,
831-844) as skyig's medium needs them, from OPAC's own files.

Usage: derive_aerosol_types.py OPAC_DIR > physics/atmosphere/aerosol_type_opac.inc
OPAC_DIR holds OPAC's configuration file opac.cfg (the components' size distributions and the
types' mixtures and height profiles) and its component files (inso00, waso00 ... waso99, soot00,
ssam00 ... , sscm00 ..., minm00, miam00, micm00, mitr00, suso00 ...), as OPAC 3.1 distributes
them. Nothing of OPAC is copied into skyig: this script mixes the components as OPAC does (a
type's coefficient is the sum of its components' per-particle coefficients times their number
densities, Hess et al. 1998 section 3) and reduces the mixture, per relative humidity class, to:
  - the extinction coefficient at 550 nm of the type's standard mixture (1/km; its ratio between
    humidities is the hygroscopic growth),
  - the single-scattering albedo at 550 nm,
  - the Angstrom exponent of the extinction, fitted over 400-700 nm,
  - the asymmetry parameter at 550 nm,
  - the phase function at 550 nm at kMiePhaseSamples angles theta_i = pi (i / (N - 1))^2 (dense
    at the forward peak), as natural logarithms, normalised so that the function the shader
    interpolates (linear in log p and in sqrt(theta)) integrates to 1 over the sphere,
and the effective aerosol scale height of the type's mixing layer (the height a uniform layer
of the ground density would have: Z (1 - exp(-Hmax / Z)), Hess et al. 1998 Table 5).
Validation printed on stderr: OPAC's continental polluted at 80% gives 0.1746 /km, 0.8925, 0.6977
(the output of OPAC's own program for that type).
"""
import math
import os
import re
import sys

import numpy as np

N = 64  # ATMOSPHERE_MIE_PHASE_SAMPLES in physics/atmosphere/parameters.glsl
RHS = [0, 50, 70, 80, 90, 95, 98, 99]
COMPONENTS = {1: 'inso', 2: 'waso', 3: 'soot', 4: 'ssam', 5: 'sscm', 6: 'minm', 7: 'miam', 8: 'micm',
              9: 'mitr', 10: 'suso'}
NUMBER = re.compile(r'-?\d\.\d+E[+-]\d+')


def read_types(directory):
    lines = open(os.path.join(directory, 'opac.cfg')).read().splitlines()
    k = [i for i, l in enumerate(lines) if 'Aerosol types and clouds' in l][0]
    types = []
    while k < len(lines):
        m = re.match(r'^(\d+)\s*:\s*([a-z ]+)$', lines[k].strip())
        if m and int(m.group(1)) <= 10 and 'number' not in lines[k]:
            count = int(lines[k + 1].split(':')[0])
            mix = []
            for j in range(count):
                index, _, density = [s.strip() for s in lines[k + 2 + j].split(':')]
                mix.append((COMPONENTS[int(index)], float(density)))
            mixing_layer = lines[k + 2 + count + 1].split()  # Hmin Hmax Z of the mixing layer
            types.append((m.group(2).strip(), mix, float(mixing_layer[1]), float(mixing_layer[2])))
            k += 2 + count
        k += 1
    return types


def read_component(directory, name, rh):
    path = os.path.join(directory, '%s%02d' % (name, rh))
    if not os.path.exists(path):  # not hygroscopic: one file for all humidities
        path = os.path.join(directory, name + '00')
    optical, phase, section, wavelengths = {}, [], 0, None
    for line in open(path).read().splitlines():
        if 'optical parameters' in line:
            section = 1
        elif 'volume phase function' in line:
            section = 2
        values = [float(x) for x in NUMBER.findall(line)]
        if section == 1 and line.startswith('#') and len(values) >= 3:
            optical[round(values[0], 4)] = values[1:]
        elif section == 2 and line.startswith('#') and '|' in line and values:
            wavelengths = values
        elif section == 2 and not line.startswith('#') and values:
            phase.append(values)
    return optical, wavelengths, np.array(phase)


def mixture(directory, mix, rh):
    ext, sca, volume_phase = {}, {}, None
    for name, density in mix:
        optical, wavelengths, phase = read_component(directory, name, rh)
        for w, v in optical.items():
            ext[w] = ext.get(w, 0.0) + density * v[0]
            sca[w] = sca.get(w, 0.0) + density * v[1]
        p = density * phase[:, wavelengths.index(0.55) + 1]
        volume_phase = p if volume_phase is None else volume_phase + p
        angles = phase[:, 0]
    return ext, sca, angles, volume_phase / sca[0.55]


def tabulate(angles, p):
    """log p at theta_i, normalised for the shader's interpolation."""
    theta = math.pi * (np.arange(N) / (N - 1)) ** 2
    table = np.interp(np.degrees(theta), angles, np.log(p))
    u = np.linspace(0.0, 1.0, 200001)
    f = np.exp(np.interp(u * (N - 1), np.arange(N), table))
    t = math.pi * u * u
    integral = np.trapz(f * 2 * math.pi * np.sin(t) * 2 * math.pi * u, u)  # dOmega = 2 pi sin t dt
    table -= math.log(integral)
    shader = np.exp(np.interp(np.sqrt(np.radians(angles) / math.pi) * (N - 1), np.arange(N), table))
    return table, np.max(np.abs(shader / (p / integral) - 1.0))


def main():
    directory = sys.argv[1]
    out = ['// Generated by physics/atmosphere/derive_aerosol_types.py from OPAC 3.1\'s files (Hess, Koepke and',
           '// Schult 1998); do not edit. Per type: name, effective scale height (m), then per relative',
           '// humidity class: RH, extinction at 550 nm (1/km, the standard mixture), single-scattering albedo,',
           '// Angstrom exponent (400-700 nm), asymmetry parameter, log phase function at theta_i = pi (i/(N-1))^2.']
    for name, mix, hmax, z in read_types(directory):
        height = 1000.0 * z * (1.0 - math.exp(-hmax / z))
        out.append('{"%s", %.0f, {{' % (name.replace(' ', '_'), height))
        for rh in RHS:
            ext, sca, angles, p = mixture(directory, mix, rh)
            mu = np.cos(np.radians(angles))
            g = np.trapz(2 * math.pi * p * mu, mu[::-1][::-1]) / np.trapz(2 * math.pi * p, mu)
            ws = [0.40, 0.45, 0.50, 0.55, 0.60, 0.65, 0.70]
            alpha = -np.polyfit(np.log(ws), np.log([ext[w] for w in ws]), 1)[0]
            table, worst = tabulate(angles, p)
            print('%-20s %2d%%: ext %.4f /km, ssa %.4f, alpha %.3f, g %.4f, table within %.2f%% of OPAC' %
                  (name, rh, ext[0.55], sca[0.55] / ext[0.55], alpha, g, 100 * worst), file=sys.stderr)
            out.append('  {%d, %.5g, %.5f, %.4f, %.4f, {%s}},' % (
                rh, ext[0.55], sca[0.55] / ext[0.55], alpha, g, ', '.join('%.4f' % v for v in table)))
        out.append('}}},')
    print('\n'.join(out))


if __name__ == '__main__':
    main()
