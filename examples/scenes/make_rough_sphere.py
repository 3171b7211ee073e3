#!/usr/bin/python3
"""Writes rough_sphere.npy, the [contact] height_map of rough_sphere_contact.toml.

The indenter is a sphere (R = 10 mm) carrying a random roughness: Gaussian white noise (fixed
seed, so the file is reproducible) smoothed by a Gaussian filter of standard deviation 3 cells
(18.75 um) in Fourier space, so that every asperity spans several of the 6.25 um cells, then
scaled to an rms height of 0.2 um, a tenth of the smooth Hertz approach a^2/R = 2.19 um at 100 N
on steel (Johnson 1985, section 4.2), which keeps the contact a rough Hertz contact
(Greenwood & Tripp 1967; Johnson 1985 section 13.4: alpha = sigma R / a^2 = 0.09) rather than
a few isolated asperities.

coatfft reads a height_map as the gap h(x, y) to the flat body, not as a topography
(docs/scene_format.md): the roughness z (positive towards the body) is subtracted from the
sphere's exact profile R - sqrt(R^2 - r^2), and the result shifted so that its smallest value,
where contact starts, is 0.

Usage: /usr/bin/python3 make_rough_sphere.py  (writes next to this script; prints the
statistics quoted in rough_sphere_contact.toml)
"""
import math
import os

import numpy as np

N = 128  # cells along x and y, as [grid] nx, ny of the scene
L = 0.8e-3  # domain side [m], as [grid] lx, ly
R = 10e-3  # sphere radius [m]
RMS = 0.2e-6  # rms roughness [m]
SMOOTHING_CELLS = 3.0  # standard deviation of the Gaussian filter [cells]
SEED = 20240611


def main():
    dx = L / N
    x = -L / 2 + (np.arange(N) + 0.5) * dx  # cell centres, as docs/scene_format.md [grid]
    X, Y = np.meshgrid(x, x)  # row j is y_j: shape (ny, nx), C order
    sphere = R - np.sqrt(R * R - X * X - Y * Y)

    rng = np.random.default_rng(SEED)
    noise = rng.standard_normal((N, N))
    k = 2 * np.pi * np.fft.fftfreq(N, d=dx)
    KX, KY = np.meshgrid(k, k)
    sigma = SMOOTHING_CELLS * dx
    smoothed = np.fft.ifft2(np.fft.fft2(noise) * np.exp(-0.5 * sigma**2 * (KX**2 + KY**2))).real
    z = smoothed - smoothed.mean()
    z *= RMS / np.sqrt(np.mean(z * z))

    gap = sphere - z
    gap -= gap.min()
    out = os.path.join(os.path.dirname(os.path.abspath(__file__)), "rough_sphere.npy")
    np.save(out, gap.astype(np.float64))

    # rms slope by central differences (periodic roughness): the quantity of the rough-contact
    # area estimates quoted in the scene.
    gx = (np.roll(z, -1, axis=1) - np.roll(z, 1, axis=1)) / (2 * dx)
    gy = (np.roll(z, -1, axis=0) - np.roll(z, 1, axis=0)) / (2 * dx)
    slope = math.sqrt(np.mean(gx * gx + gy * gy))
    print(f"wrote {out}: shape {gap.shape}, rms roughness {math.sqrt(np.mean(z * z)):.3e} m, "
          f"rms slope {slope:.4f}, peak-to-valley {z.max() - z.min():.3e} m")


if __name__ == "__main__":
    main()
