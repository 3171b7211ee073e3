"""Measured topographies from Python and from `coatfft topography`, on files written here by numpy
and netCDF4: sizes, orientation (x along columns), units, rms height, missing points, refusals."""
import json
import subprocess

import netCDF4
import numpy as np
import pytest

import coatfft


def z_of(nx, ny):
    """1 + i + 10 j at column i, row j: a transpose or a flip shows."""
    j, i = np.mgrid[0:ny, 0:nx]
    return 1.0 + i + 10.0 * j


def write_surface_topography_nc(path, z, lx, ly, unit, periodic, fmt="NETCDF3_64BIT_OFFSET"):
    """SurfaceTopography's layout: heights(x, y), the first index along x."""
    with netCDF4.Dataset(path, "w", format=fmt) as nc:
        ny, nx = z.shape
        nc.createDimension("x", nx)
        nc.createDimension("y", ny)
        for name, n, length in (("x", nx, lx), ("y", ny, ly)):
            v = nc.createVariable(name, "f8", (name,))
            v.length = length
            v.periodic = 1 if periodic else 0
            v.length_unit = unit
            v[:] = (np.arange(n) + 0.5) * length / n
        nc.createVariable("heights", "f8", ("x", "y"))[:] = z.T


@pytest.mark.parametrize("fmt", ["NETCDF3_64BIT_OFFSET", "NETCDF4"])
def test_netcdf_in_surface_topography_layout(tmp_path, fmt):
    z = z_of(5, 3)
    path = tmp_path / "t.nc"
    write_surface_topography_nc(path, z, 10.0, 6.0, "µm", True, fmt)
    t = coatfft.read_topography(path)
    assert t["heights"].shape == (3, 5)
    assert np.array_equal(t["heights"], z * 1e-6)
    assert (t["lx"], t["ly"], t["periodic"], t["unit"], t["format"]) == \
        (pytest.approx(10e-6), pytest.approx(6e-6), True, "µm", "netcdf")


def test_netcdf_in_xarray_order_with_fill_values(tmp_path):
    z = z_of(4, 6)
    path = tmp_path / "xr.nc"
    with netCDF4.Dataset(path, "w") as nc:
        nc.createDimension("y", 6)
        nc.createDimension("x", 4)
        v = nc.createVariable("heights", "f4", ("y", "x"), fill_value=-1.0)
        v.units = "nm"
        zz = z.copy()
        zz[2, 3] = -1.0
        v[:] = zz
    with pytest.raises(ValueError, match="1 of 24 points are missing"):
        coatfft.read_topography(path)
    t = coatfft.read_topography(path, missing="fill")
    assert t["missing"] == 1 and t["lx"] is None and t["periodic"] is None
    # The hole's value is the mean of its neighbours (the harmonic rule), here all known.
    expected = z * 1e-9
    expected[2, 3] = np.mean([z[1, 3], z[3, 3], z[2, 2]]) * 1e-9
    assert np.allclose(t["heights"], expected, rtol=1e-6, atol=0)


def test_npy_and_text_files_with_units_and_detrending(tmp_path):
    z = z_of(6, 4)
    np.save(tmp_path / "f.npy", np.asfortranarray(z.astype(np.float32)))
    t = coatfft.read_topography(tmp_path / "f.npy", unit="mm")
    assert np.array_equal(t["heights"], z * 1e-3)
    # A plane is removed exactly; the mean too.
    assert np.abs(coatfft.read_topography(tmp_path / "f.npy", detrend="plane")["heights"]).max() < 1e-12
    np.savetxt(tmp_path / "f.txt", z, delimiter="\t", header="heights in nm")
    assert np.allclose(coatfft.read_topography(tmp_path / "f.txt", unit="nm")["heights"], z * 1e-9,
                       rtol=1e-15)
    with pytest.raises(ValueError, match='unknown unit "furlong"'):
        coatfft.read_topography(tmp_path / "f.npy", unit="furlong")
    with pytest.raises(ValueError, match="detrend"):
        coatfft.read_topography(tmp_path / "f.npy", detrend="tilt")


def test_xyz_rows_in_any_order(tmp_path):
    z = z_of(5, 4)
    j, i = np.mgrid[0:4, 0:5]
    rows = np.column_stack([0.2 * i.ravel(), 0.5 * j.ravel(), z.ravel()])
    rows = rows[np.random.default_rng(3).permutation(len(rows))]
    np.savetxt(tmp_path / "r.xyz", rows, header="x y z")
    t = coatfft.read_topography(tmp_path / "r.xyz", unit="um")
    assert t["format"] == "xyz"
    assert np.allclose(t["heights"], z * 1e-6, rtol=1e-14)
    assert t["lx"] == pytest.approx(1e-6) and t["ly"] == pytest.approx(2e-6)
    rows[0, 0] += 0.05  # one x off the grid
    np.savetxt(tmp_path / "bad.xyz", rows)
    with pytest.raises(ValueError, match="do not make a regular grid"):
        coatfft.read_topography(tmp_path / "bad.xyz")


def test_program_prints_the_summary_and_writes_netcdf(coatfft_exe, tmp_path):
    rng = np.random.default_rng(5)
    z = rng.normal(size=(12, 16))
    src = tmp_path / "in.nc"
    write_surface_topography_nc(src, z, 8.0, 6.0, "nm", False)
    out = tmp_path / "out.nc"
    run = subprocess.run([coatfft_exe, "topography", str(src), "--detrend", "mean", "-o", str(out)],
                         check=True, capture_output=True, text=True)
    s = json.loads(run.stdout)
    zm = (z - z.mean()) * 1e-9
    assert (s["format"], s["nx"], s["ny"], s["unit"], s["periodic"], s["missing"]) == \
        ("netcdf", 16, 12, "nm", False, 0)
    assert s["lx"] == pytest.approx(8e-9) and s["ly"] == pytest.approx(6e-9)
    assert s["rms_height"] == pytest.approx(np.sqrt(np.mean(zm**2)), rel=1e-12)
    assert (s["min"], s["max"]) == (pytest.approx(zm.min()), pytest.approx(zm.max()))
    # Sdq by neighbours' differences within the map (not periodic).
    dx, dy = 8e-9 / 16, 6e-9 / 12
    slope2 = np.mean((np.diff(zm, axis=1) / dx) ** 2) + np.mean((np.diff(zm, axis=0) / dy) ** 2)
    assert s["rms_slope"] == pytest.approx(np.sqrt(slope2), rel=1e-12)
    with netCDF4.Dataset(out) as nc:
        assert nc["heights"].dimensions == ("x", "y")
        assert np.abs(np.asarray(nc["heights"]).T - zm).max() <= 1e-15 * np.abs(zm).max()
        assert (nc["x"].length, nc["y"].length, nc["x"].periodic) == \
            (pytest.approx(8e-9), pytest.approx(6e-9), 0)
    # The file written is read back as it was written.
    t = coatfft.read_topography(out)
    assert np.array_equal(t["heights"], np.asarray(netCDF4.Dataset(out)["heights"]).T)


def test_program_refuses_bad_files_without_output(coatfft_exe, tmp_path):
    out = tmp_path / "o.npy"
    cases = {
        "nan.npy": lambda p: np.save(p, np.array([[1.0, np.nan], [2.0, 3.0]])),
        "cut.nc": lambda p: p.write_bytes(b"CDF\x02\x00\x00"),
        "u.csv": lambda p: p.write_text("1,2\n3,4\n"),
    }
    for name, write in cases.items():
        write(tmp_path / name)
        extra = ["--unit", "inch"] if name == "u.csv" else []
        run = subprocess.run([coatfft_exe, "topography", str(tmp_path / name), "-o", str(out),
                              *extra], capture_output=True, text=True)
        assert run.returncode == 2, run.stderr
        assert run.stderr.count("\n") == 1 and name in run.stderr or "inch" in run.stderr
        assert not out.exists()
