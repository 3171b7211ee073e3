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


def test_program_writes_the_gap_a_flat_sees(coatfft_exe, tmp_path):
    # A tilted map in nm: --gap writes max(z) - z of the heights less their least-squares plane
    # (numpy's lstsq over the cell centres), in metres, ready for indenter = "height_map".
    rng = np.random.default_rng(8)
    ny, nx = 10, 14
    y, x = np.mgrid[0:ny, 0:nx] + 0.5
    z = rng.normal(size=(ny, nx)) + 0.3 * x - 0.2 * y + 5.0
    src = tmp_path / "tilted.nc"
    write_surface_topography_nc(src, z, 7.0, 5.0, "nm", True)
    out = tmp_path / "gap.npy"
    subprocess.run([coatfft_exe, "topography", str(src), "--detrend", "plane", "--gap", "-o",
                    str(out)], check=True, capture_output=True, text=True)
    a = np.column_stack([np.ones(z.size), x.ravel(), y.ravel()])
    zd = (z - (a @ np.linalg.lstsq(a, z.ravel(), rcond=None)[0]).reshape(z.shape)) * 1e-9
    gap = np.load(out)
    assert gap.min() == 0.0
    assert np.abs(gap - (zd.max() - zd)).max() <= 1e-12 * np.abs(zd).max()
    # The gap is no height map of SurfaceTopography's layout, and it needs a file to go to.
    for args, says in (([str(src), "--gap", "-o", str(tmp_path / "gap.nc")], "written as .npy"),
                       ([str(src), "--gap"], "--gap needs -o")):
        run = subprocess.run([coatfft_exe, "topography", *args], capture_output=True, text=True)
        assert run.returncode == 2 and run.stderr.count("\n") == 1 and says in run.stderr
    assert not (tmp_path / "gap.nc").exists()


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


SCENE_BODY = """
[substrate]
material = "steel"

[[coating]]
material = "titanium_nitride"
thickness = 2.0e-5
"""


def test_periodic_contact_from_netcdf_equals_the_gap_and_typed_grid(tmp_path):
    grid = coatfft.Grid(32, 32, 0.4e-3, 0.4e-3)
    z = coatfft.self_affine_surface(grid, hurst=0.8, rms_slope=0.1, seed=4)
    write_surface_topography_nc(tmp_path / "z.nc", z, 0.4e-3, 0.4e-3, "m", True)
    np.save(tmp_path / "gap.npy", z.max() - z)
    # No [grid]: its sizes and the periodic boundary come from the file.
    (tmp_path / "nc.toml").write_text(SCENE_BODY + '[contact]\ntopography = "z.nc"\nload = 2.0\n')
    (tmp_path / "typed.toml").write_text(
        '[grid]\nnx = 32\nny = 32\nlx = 0.4e-3\nly = 0.4e-3\nboundary = "periodic"\n' + SCENE_BODY
        + '[contact]\nindenter = "height_map"\npath = "gap.npy"\nload = 2.0\n')
    a = coatfft.run_scene(tmp_path / "nc.toml")
    b = coatfft.run_scene(tmp_path / "typed.toml")
    assert a["summary"]["converged"] and b["summary"]["converged"]
    assert a["summary"]["boundary"] == "periodic"
    assert np.array_equal(a["pressure"], b["pressure"])
    assert np.array_equal(a["uz"], b["uz"])
    assert a["summary"]["iterations"] == b["summary"]["iterations"]
    t = a["summary"]["topography"]
    assert (t["format"], t["nx"], t["periodic"], t["file"]) == ("netcdf", 32, True, str(tmp_path / "z.nc"))
    # A periodic map joins its copies: the edge jump is a step like the others.
    assert 0.3 < t["edge_mismatch"]["ratio"] < 3


def test_grid_keys_from_a_topography_are_checked(tmp_path):
    z = z_of(6, 4)
    write_surface_topography_nc(tmp_path / "z.nc", z, 6e-3, 4e-3, "um", False)
    np.save(tmp_path / "z.npy", z)
    cases = [
        ('[grid]\nnx = 8\n', "z.nc", "nx = 8 disagrees with the topography"),
        ('[grid]\nlx = 5e-3\n', "z.nc", "lx = 0.005 disagrees"),
        ('[grid]\nboundary = "periodic"\nnx = 6\n', "z.nc", None),
        ("", "z.npy", "carries no size; give \\[grid\\] lx and ly"),
        ('[grid]\nrefine = "auto"\n', "z.nc", "refine"),
    ]
    for k, (grid, file, message) in enumerate(cases):
        scene = tmp_path / f"s{k}.toml"
        scene.write_text(grid + SCENE_BODY + f'[contact]\ntopography = "{file}"\nload = 1e-3\n')
        if message is None:
            s = coatfft.run_scene(scene)["summary"]
            assert s["boundary"] == "periodic" and s["topography"]["edge_mismatch"]["ratio"] > 1
        else:
            with pytest.raises(ValueError, match=message):
                coatfft.run_scene(scene)
    # A file that does not say it is periodic is solved on a free boundary by default.
    scene = tmp_path / "free.toml"
    scene.write_text(SCENE_BODY + '[contact]\ntopography = "z.nc"\nload = 1e-3\n')
    s = coatfft.run_scene(scene)["summary"]
    assert s["boundary"] == "free" and s["topography"]["edge_mismatch"] is None


def test_run_writes_netcdf_equal_to_its_npy_files(coatfft_exe, tmp_path):
    grid = coatfft.Grid(16, 12, 0.2e-3, 0.15e-3)
    z = coatfft.self_affine_surface(grid, hurst=0.7, rms_slope=0.1, seed=1)
    write_surface_topography_nc(tmp_path / "z.nc", z, 0.2e-3, 0.15e-3, "m", True)
    sweep = SCENE_BODY + '[contact]\ntopography = "z.nc"\nload = [0.5, 1.0]\n'
    stress = (SCENE_BODY + '[contact]\ntopography = "z.nc"\nload = 1.0\n'
              '[stress]\ndepths = [1e-5, 3e-5]\nsection = "xz"\ndepth_max = 4e-5\nnz = 4\n')
    for case, body in (("sweep", sweep), ("stress", stress)):
        (tmp_path / f"{case}_npy.toml").write_text(body)
        (tmp_path / f"{case}_nc.toml").write_text(body + '[output]\nformat = "netcdf"\n')
        for name in ("npy", "nc"):
            subprocess.run([coatfft_exe, "run", str(tmp_path / f"{case}_{name}.toml"), "-o",
                            str(tmp_path / f"{case}_{name}"), "--quiet"], check=True,
                           capture_output=True)
        assert not list((tmp_path / f"{case}_nc").glob("*.npy"))
        assert (tmp_path / f"{case}_nc" / "summary.json").exists()
    # Each map over (..., x, y): the .npy array with its last two axes swapped.
    def same_maps(case, names):
        with netCDF4.Dataset(tmp_path / f"{case}_nc" / "fields.nc") as nc:
            assert nc["x"].length == pytest.approx(0.2e-3) and nc["x"].periodic == 1
            assert np.allclose(nc["x"][:], grid.x) and np.allclose(nc["y"][:], grid.y)
            for name in names:
                assert nc[name].dimensions[-2:] == ("x", "y")
                assert np.array_equal(np.swapaxes(np.asarray(nc[name]), -1, -2),
                                      np.load(tmp_path / f"{case}_npy" / f"{name}.npy"))
            assert nc["pressure"].units == "Pa"
            return json.loads(nc.summary)
    summary = same_maps("sweep", ("uz", "pressure", "gap"))
    assert (tmp_path / "sweep_nc" / "sweep.csv").exists()
    with netCDF4.Dataset(tmp_path / "sweep_nc" / "fields.nc") as nc:
        assert np.allclose(nc["load"][:], [0.5, 1.0]) and nc["uz"].dimensions[0] == "sweep"
    assert summary["sweep"] == json.loads((tmp_path / "sweep_npy" / "summary.json").read_text())["sweep"]
    # The body, from the scene: TiN (its E, nu) 20 um thick, bonded, on steel.
    coating = coatfft.material("titanium_nitride")
    assert summary["body"]["coatings"] == [{"E": coating.E, "nu": coating.nu, "thickness": 2e-5,
                                            "interface_below": "bonded"}]
    same_maps("stress", ("uz", "pressure", "gap", "ux", "uy", "stress", "von_mises",
                         "stress_interfaces", "von_mises_interfaces"))
    with netCDF4.Dataset(tmp_path / "stress_nc" / "fields.nc") as nc:
        for name in ("stress_section", "von_mises_section"):
            assert np.array_equal(np.asarray(nc[name]), np.load(tmp_path / "stress_npy" / f"{name}.npy"))
        assert np.array_equal(nc["depth"][:], [1e-5, 3e-5])
        assert np.allclose(nc["section_depth"][:], [1e-5, 2e-5, 3e-5, 4e-5])
        assert nc["stress"].dimensions == ("depth", "component", "x", "y")
        assert nc["stress_interfaces"].dimensions == ("interface", "side", "component", "x", "y")
        assert np.array_equal(nc["interface"][:], [2e-5]) and len(nc.dimensions["side"]) == 2


def test_surface_written_as_netcdf_is_the_npy_surface(coatfft_exe, tmp_path):
    flags = ["--nx", "16", "--ny", "8", "--lx", "1e-3", "--ly", "5e-4", "--hurst", "0.8",
             "--rms-height", "1e-6", "--seed", "9"]
    for name in ("s.npy", "s.nc"):
        subprocess.run([coatfft_exe, "surface", "-o", str(tmp_path / name), *flags], check=True,
                       capture_output=True)
    with netCDF4.Dataset(tmp_path / "s.nc") as nc:
        assert np.array_equal(np.asarray(nc["heights"]).T, np.load(tmp_path / "s.npy"))
        assert (nc["x"].length, nc["y"].length, nc["x"].periodic, nc["y"].periodic) == \
            (1e-3, 5e-4, 1, 1)
    t = coatfft.read_topography(tmp_path / "s.nc")
    assert t["periodic"] is True and np.array_equal(t["heights"], np.load(tmp_path / "s.npy"))


def test_pad_leaves_a_free_map_as_it_is_and_frees_a_periodic_one(tmp_path):
    grid = coatfft.Grid(24, 24, 0.3e-3, 0.3e-3)
    z = coatfft.self_affine_surface(grid, hurst=0.8, rms_slope=0.1, seed=6)
    write_surface_topography_nc(tmp_path / "z.nc", z, 0.3e-3, 0.3e-3, "m", False)

    # A homogeneous body: its DC-FFT influence coefficients are exact on any grid (a coated
    # body's are its FRF's quadrature, chosen afresh on each grid to the method's tolerance).
    def pressure(grid_keys):
        scene = tmp_path / "s.toml"
        scene.write_text(grid_keys + '[substrate]\nmaterial = "steel"\n' +
                         '[contact]\ntopography = "z.nc"\nload = 80.0\ntolerance = 1e-13\n')
        run = coatfft.run_scene(scene)
        pad = run["summary"]["topography"]["pad"]
        assert run["summary"]["converged"]
        return run["pressure"][pad:pad + 24, pad:pad + 24], run["summary"]

    free, s = pressure("")
    assert s["boundary"] == "free" and s["topography"]["pad"] == 0
    # On a free boundary the half-space beyond the map carries no load anyway: a pad changes
    # nothing on the map (to the solver's tolerance).
    padded, s = pressure("[grid]\npad = 8\n")
    assert s["nx"] == 40 and s["lx"] == pytest.approx(0.5e-3)
    assert np.abs(padded - free).max() <= 1e-8 * free.max()
    # A periodic run approaches the free map as its copies move apart.
    errors = [np.abs(pressure(f'[grid]\nboundary = "periodic"\npad = {p}\n')[0] - free).max()
              for p in (0, 8, 24)]
    assert errors[0] > errors[1] > errors[2]


def test_pad_out_of_reach_is_checked(tmp_path):
    z = z_of(8, 8) * 1e-7
    write_surface_topography_nc(tmp_path / "z.nc", z, 1e-3, 1e-3, "m", False)
    gap = z.max() - z.min()
    scene = tmp_path / "s.toml"
    scene.write_text("[grid]\npad = 4\n" + SCENE_BODY +
                     f'[contact]\ntopography = "z.nc"\napproach = {3 * gap}\n')
    with pytest.raises(ValueError, match="reaches the pad"):
        coatfft.run_scene(scene)


def write_x3p(path, z_counts, increment_z, offset_z, dx, dy, valid=None, spoil_md5=False):
    """An ISO 25178-72 archive written by Python's zipfile: int32 counts (x fastest), their
    increment and offset on CZ, an optional valid-points bit mask, MD5 sums by hashlib."""
    import hashlib
    import zipfile
    ny, nx = z_counts.shape
    data = z_counts.astype("<i4").tobytes()
    link = (f"<PointDataLink>bindata/data.bin</PointDataLink>"
            f"<MD5ChecksumPointData>{hashlib.md5(data).hexdigest()}</MD5ChecksumPointData>")
    if valid is not None:
        bits = np.packbits(valid.ravel().astype(np.uint8), bitorder="little").tobytes()
        link += (f"<ValidPointsLink>bindata/valid.bin</ValidPointsLink>"
                 f"<MD5ChecksumValidPoints>{hashlib.md5(bits).hexdigest()}</MD5ChecksumValidPoints>")
    xml = f"""<?xml version="1.0" encoding="UTF-8"?>
<p:ISO5436_2 xmlns:p="http://www.opengps.eu/2008/ISO5436_2">
 <Record1><Revision>ISO5436 - 2000</Revision><FeatureType>SUR</FeatureType><Axes>
  <CX><AxisType>I</AxisType><DataType>D</DataType><Increment>{dx!r}</Increment><Offset>0</Offset></CX>
  <CY><AxisType>I</AxisType><DataType>D</DataType><Increment>{dy!r}</Increment><Offset>0</Offset></CY>
  <CZ><AxisType>A</AxisType><DataType>L</DataType><Increment>{increment_z!r}</Increment><Offset>{offset_z!r}</Offset></CZ>
 </Axes></Record1>
 <Record2><Date>2026-01-02T03:04:05+00:00</Date><Creator>pytest</Creator>
  <Instrument><Manufacturer>None</Manufacturer><Model>zipfile</Model><Serial>0</Serial><Version>1</Version></Instrument>
  <CalibrationDate>2026-01-01T00:00:00+00:00</CalibrationDate>
  <ProbingSystem><Type>NonContacting</Type><Identification>none</Identification></ProbingSystem>
 </Record2>
 <Record3><MatrixDimension><SizeX>{nx}</SizeX><SizeY>{ny}</SizeY><SizeZ>1</SizeZ></MatrixDimension>
  <DataLink>{link}</DataLink></Record3>
 <Record4><ChecksumFile>md5checksum.hex</ChecksumFile></Record4>
</p:ISO5436_2>
""".encode()
    md5 = hashlib.md5(xml + (b" " if spoil_md5 else b"")).hexdigest()
    with zipfile.ZipFile(path, "w", zipfile.ZIP_DEFLATED) as archive:
        archive.writestr("main.xml", xml)
        archive.writestr("md5checksum.hex", f"{md5} *main.xml\n")
        archive.writestr("bindata/data.bin", data)
        if valid is not None:
            archive.writestr("bindata/valid.bin", bits)


def test_x3p_written_by_zipfile(coatfft_exe, tmp_path):
    counts = (z_of(7, 5) - 20).astype(np.int64) * 1000
    write_x3p(tmp_path / "s.x3p", counts, 1e-12, 2e-9, 0.5e-6, 0.25e-6)
    t = coatfft.read_topography(tmp_path / "s.x3p")
    expected = counts * 1e-12 + 2e-9
    assert t["format"] == "x3p" and t["heights"].shape == (5, 7)
    assert np.allclose(t["heights"], expected, rtol=1e-15, atol=1e-24)
    assert (t["lx"], t["ly"]) == (pytest.approx(3.5e-6), pytest.approx(1.25e-6))
    assert t["metadata"]["creator"] == "pytest"
    # Invalid points by the mask: refused, or filled.
    valid = np.ones((5, 7), bool)
    valid[2, 3] = False
    write_x3p(tmp_path / "v.x3p", counts, 1e-12, 0.0, 0.5e-6, 0.25e-6, valid=valid)
    with pytest.raises(ValueError, match="1 of 35 points are missing"):
        coatfft.read_topography(tmp_path / "v.x3p")
    # Bad files: one line, exit 2, no output.
    write_x3p(tmp_path / "md5.x3p", counts, 1e-12, 0.0, 0.5e-6, 0.25e-6, spoil_md5=True)
    (tmp_path / "cut.x3p").write_bytes((tmp_path / "s.x3p").read_bytes()[:200])
    for name, message in (("md5.x3p", "MD5"), ("cut.x3p", "cut.x3p")):
        run = subprocess.run([coatfft_exe, "topography", str(tmp_path / name), "-o",
                              str(tmp_path / "o.nc")], capture_output=True, text=True)
        assert run.returncode == 2 and message in run.stderr and run.stderr.count("\n") == 1
        assert not (tmp_path / "o.nc").exists()


def test_read_topography_names_its_keyword_and_takes_a_memory_limit(tmp_path):
    # One known point on 64^2: 4095 points to fill, 2 MB before the factor (512 bytes each).
    z = np.full((64, 64), np.nan)
    z[3, 5] = 1e-6
    np.save(tmp_path / "one.npy", z)
    with pytest.raises(ValueError, match=r"can be filled \(missing='fill'"):
        coatfft.read_topography(tmp_path / "one.npy")
    with pytest.raises(ValueError, match=r"one\.npy: filling the missing points .* 4095 missing"):
        coatfft.read_topography(tmp_path / "one.npy", missing="fill", max_memory="1M")
    with pytest.raises(ValueError, match="max_memory"):
        coatfft.read_topography(tmp_path / "one.npy", missing="fill", max_memory="lots")
    # With room: one known point makes the map flat (to the fill's rounding).
    t = coatfft.read_topography(tmp_path / "one.npy", missing="fill", max_memory="1G")
    assert np.allclose(t["heights"], 1e-6, rtol=1e-9, atol=0)
