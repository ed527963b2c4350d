#!/usr/bin/env python3
"""Write the Klems BSDF of a venetian blind of flat, Lambertian slats (an LBNL WINDOW BSDF XML
file, Visible only) by Monte Carlo ray tracing in the slats' profile.

The model: slats infinitely long along the local x axis (horizontal when the BSDF's up vector
is vertical), width W, spacing S, tilt PSI from the open (perpendicular to the window)
position, both faces Lambertian with reflectance RHO, opaque. No glazing. Local frame as in
docs/materials.md "Measured BSDF (Klems)": y up, z the surface normal pointing into the room
(WINDOW's back), the front (outside) at -z. For each incoming patch of the LBNL/Klems Full
basis and each side, RAYS rays start at uniform positions over one slat period, their
directions uniform in projected solid angle over the patch (the Klems basis' own measure),
and are traced through diffuse slat reflections until they leave the slat layer; the exit
direction's patch (propagation-direction rule) and side give
    f(i, j) = (fraction of patch i's rays leaving in patch j) / Lambda_j.
The result is a plausible blind BSDF for tests and examples, not a measured product: its
statistical noise is that of RAYS rays per patch, and T + R = 1 - absorbed exactly per ray.

Usage: python3 scripts/make_blind_bsdf.py > projects/bsdf_blind/blind_45deg.xml
(the committed file was written with the defaults below; deterministic: fixed seed).
"""
import math
import random
import sys

W = 0.025        # slat width, m
S = 0.020        # slat spacing, m
PSI_DEG = 45.0   # tilt: the slats' room-side edge higher than their outside edge (sun-blocking)
RHO = 0.70       # slat reflectance (both faces, Lambertian)
RAYS = 4000      # rays per incoming patch and side
SEED = 17

THETA_BOUNDS = [0, 5, 15, 25, 35, 45, 55, 65, 75, 90]
PHI_COUNTS = [1, 8, 16, 20, 24, 24, 24, 16, 12]


def patches():
    out = []
    for r, n in enumerate(PHI_COUNTS):
        for k in range(n):
            out.append((r, k))
    return out


PATCHES = patches()
N = len(PATCHES)
FIRST = [sum(PHI_COUNTS[:r]) for r in range(len(PHI_COUNTS))]


def lam(index):
    r, _ = PATCHES[index]
    lo, hi = math.radians(THETA_BOUNDS[r]), math.radians(THETA_BOUNDS[r + 1])
    return math.pi * (math.sin(hi) ** 2 - math.sin(lo) ** 2) / PHI_COUNTS[r]


def patch_of(v):
    theta = math.degrees(math.acos(min(1.0, abs(v[2]))))
    r = 0
    while r + 1 < len(PHI_COUNTS) and theta >= THETA_BOUNDS[r + 1]:
        r += 1
    n = PHI_COUNTS[r]
    if n == 1:
        return FIRST[r]
    phi = math.atan2(v[1], v[0])
    if phi < 0:
        phi += 2 * math.pi
    k = int(math.floor(phi * n / (2 * math.pi) + 0.5)) % n
    return FIRST[r] + k


def sample_patch(index, rng):
    r, k = PATCHES[index]
    lo, hi = math.radians(THETA_BOUNDS[r]), math.radians(THETA_BOUNDS[r + 1])
    s2 = math.sin(lo) ** 2 + rng.random() * (math.sin(hi) ** 2 - math.sin(lo) ** 2)
    n = PHI_COUNTS[r]
    phi = 2 * math.pi * rng.random() if n == 1 else 2 * math.pi / n * (k - 0.5 + rng.random())
    st = math.sqrt(s2)
    return [st * math.cos(phi), st * math.sin(phi), math.sqrt(max(0.0, 1 - s2))]


PSI = math.radians(PSI_DEG)
U = (math.sin(PSI), math.cos(PSI))        # slat direction in (y, z): the room-side edge higher
NRM = (math.cos(PSI), -math.sin(PSI))     # a slat normal in (y, z)
ZMAX = 0.5 * W * math.cos(PSI)


def hit_slat(y, z, dy, dz):
    """Nearest slat hit (t, k) of the profile ray, or None."""
    best = None
    k0 = math.floor(y / S)
    for k in range(k0 - 2, k0 + 4):
        # (y, z) + t (dy, dz) = (k S, 0) + a U
        det = dy * (-U[1]) - dz * (-U[0])
        if abs(det) < 1e-15:
            continue
        ry, rz = k * S - y, -z
        t = (ry * (-U[1]) - rz * (-U[0])) / det
        a = (dy * rz - dz * ry) / det
        if t > 1e-12 and abs(a) <= 0.5 * W and (best is None or t < best[0]):
            best = (t, k)
    return best


def trace(d, rng):
    """Follow one ray entering the slat layer; returns (exit direction, side) or None."""
    y = rng.random() * S
    z = -ZMAX if d[2] > 0 else ZMAX
    for _ in range(1000):
        h = hit_slat(y, z, d[1], d[2])
        if h is None:
            return d
        t, _ = h
        # Leaving the layer before the hit?
        if d[2] != 0:
            t_exit = ((ZMAX if d[2] > 0 else -ZMAX) - z) / d[2]
            if 0 < t_exit < t:
                return d
        y, z = y + t * d[1], z + t * d[2]
        if rng.random() >= RHO:
            return None
        # Lambertian reflection about the slat normal on the side the ray came from.
        ny, nz = NRM
        if d[1] * ny + d[2] * nz > 0:
            ny, nz = -ny, -nz
        u1, u2 = rng.random(), rng.random()
        r, phi = math.sqrt(u1), 2 * math.pi * u2
        lx, ly, lc = r * math.cos(phi), r * math.sin(phi), math.sqrt(1 - u1)
        # frame: x axis (along the slat), tangent in the profile, normal
        ty, tz = -nz, ny
        d = [lx, ly * ty + lc * ny, ly * tz + lc * nz]
    return None


def main():
    rng = random.Random(SEED)
    lams = [lam(j) for j in range(N)]
    # matrices[name][i][j]
    names = ["Transmission Front", "Transmission Back", "Reflection Front", "Reflection Back"]
    m = {name: [[0.0] * N for _ in range(N)] for name in names}
    for side in ("Front", "Back"):
        for i in range(N):
            counts_t = [0] * N
            counts_r = [0] * N
            for _ in range(RAYS):
                v = sample_patch(i, rng)
                # Front incidence moves toward +z (from the outside at -z).
                d = v if side == "Front" else [v[0], v[1], -v[2]]
                out = trace(d, rng)
                if out is None:
                    continue
                j = patch_of(out)
                if (out[2] > 0) == (d[2] > 0):
                    counts_t[j] += 1
                else:
                    counts_r[j] += 1
            for j in range(N):
                m["Transmission " + side][i][j] = counts_t[j] / RAYS / lams[j]
                m["Reflection " + side][i][j] = counts_r[j] / RAYS / lams[j]
    w = sys.stdout.write
    w('<?xml version="1.0" encoding="UTF-8"?>\n')
    w('<!-- A venetian blind of flat Lambertian slats, written by scripts/make_blind_bsdf.py:\n'
      '     width %g m, spacing %g m, tilt %g degrees, reflectance %g, %d rays per patch and side. -->\n'
      % (W, S, PSI_DEG, RHO, RAYS))
    w('<WindowElement xmlns="http://windows.lbl.gov">\n  <WindowElementType>System</WindowElementType>\n')
    w('  <Optical>\n    <Layer>\n      <Material>\n        <Name>Venetian blind, flat Lambertian slats</Name>\n')
    w('        <DeviceType>Venetian blind</DeviceType>\n        <Thickness unit="Millimeter">%g</Thickness>\n'
      '      </Material>\n' % (2000 * ZMAX))
    w('      <DataDefinition>\n        <IncidentDataStructure>Columns</IncidentDataStructure>\n')
    w('        <AngleBasis>\n          <AngleBasisName>LBNL/Klems Full</AngleBasisName>\n')
    for r, n in enumerate(PHI_COUNTS):
        theta = 0 if r == 0 else 0.5 * (THETA_BOUNDS[r] + THETA_BOUNDS[r + 1])
        w('          <AngleBasisBlock>\n            <Theta>%g</Theta>\n            <nPhis>%d</nPhis>\n'
          '            <ThetaBounds>\n              <LowerTheta>%g</LowerTheta>\n'
          '              <UpperTheta>%g</UpperTheta>\n            </ThetaBounds>\n          </AngleBasisBlock>\n'
          % (theta, n, THETA_BOUNDS[r], THETA_BOUNDS[r + 1]))
    w('        </AngleBasis>\n      </DataDefinition>\n')
    w('      <WavelengthData>\n        <LayerNumber>System</LayerNumber>\n'
      '        <Wavelength unit="Integral">Visible</Wavelength>\n')
    for name in names:
        w('        <WavelengthDataBlock>\n          <WavelengthDataDirection>%s</WavelengthDataDirection>\n'
          '          <ColumnAngleBasis>LBNL/Klems Full</ColumnAngleBasis>\n'
          '          <RowAngleBasis>LBNL/Klems Full</RowAngleBasis>\n'
          '          <ScatteringDataType>%s</ScatteringDataType>\n          <ScatteringData>\n'
          % (name, "BTDF" if name.startswith("Transmission") else "BRDF"))
        for o in range(N):  # Columns: one line per outgoing patch
            w(" ".join("%.3g" % m[name][i][o] for i in range(N)) + "\n")
        w('          </ScatteringData>\n        </WavelengthDataBlock>\n')
    w('      </WavelengthData>\n    </Layer>\n  </Optical>\n</WindowElement>\n')


if __name__ == "__main__":
    main()
