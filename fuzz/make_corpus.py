#!/usr/bin/env python3
"""Writes the seed corpora of the libFuzzer targets into fuzz/corpus/<target>/.

Small valid inputs (and a few near misses) from which libFuzzer mutates: the example scenes and
scenes using every section and key, .npy files of every header version and layout the reader
accepts, CSV files with comments, separators and the numbers' corner cases, and topography
files of each format (NetCDF-3 ones below netcdf_seeds). Uses only the standard library; rerun
after changing it and commit the files it writes.
Usage: fuzz/make_corpus.py
"""
import pathlib
import shutil
import struct

ROOT = pathlib.Path(__file__).resolve().parent
REPO = ROOT.parent


def npy(major, header, values, pad=True):
    """A .npy file of format `major`.0: header dict text, then little-endian float64 values."""
    length_format = "<H" if major == 1 else "<I"
    preamble = 8 + struct.calcsize(length_format)
    if pad:
        header += " " * ((64 - (preamble + len(header) + 1) % 64) % 64) + "\n"
    data = b"".join(struct.pack("<d", v) for v in values)
    return (b"\x93NUMPY" + bytes([major, 0]) + struct.pack(length_format, len(header))
            + header.encode("latin-1") + data)


def npy_seeds():
    dict_ = "{{'descr': '<f8', 'fortran_order': False, 'shape': {}, }}"
    return {
        "1x1.npy": npy(1, dict_.format("(1, 1)"), [1.5]),
        "3x4.npy": npy(1, dict_.format("(3, 4)"), [0.25 * k for k in range(12)]),
        "2x3_special.npy": npy(1, dict_.format("(2, 3)"),
                               [0.0, -0.0, 5e-324, 1e308, float("inf"), float("nan")]),
        "v2.npy": npy(2, "{'descr': '<f8', 'fortran_order': False, 'shape': (2, 2)}",
                      [1, 2, 3, 4]),
        "v3_unpadded.npy": npy(3, '{"descr": "=f8", "fortran_order": False, "shape": ( 1 ,2 ,)}',
                               [7, 8], pad=False),
        "int_dtype.npy": npy(1, "{'descr': '<i4', 'fortran_order': False, 'shape': (2, 2), }",
                             [0, 0]),
        "fortran.npy": npy(1, "{'descr': '<f8', 'fortran_order': True, 'shape': (2, 1), }",
                           [1, 2]),
        "vector.npy": npy(1, dict_.format("(3,)"), [1, 2, 3]),
    }


def csv_seeds():
    return {
        "plain.csv": "1,2,3\n4,5,6\n",
        "blanks_comments.csv": "# heights [m]\n1 2 3  # first row\n\n4\t5\t6\n",
        "semicolons_crlf.csv": "1;2;3\r\n4;5;6\r\n",
        "numbers.csv": "+1.5, -2.5e-3, 1e-400, 4.9e-324\ninf, -inf, nan, 1E+300\n",
        "single.csv": "42",
        "ragged.csv": "1, 2\n3\n",
        "word.csv": "1, x\n",
    }


def scene_seeds():
    grid = "[grid]\nnx = 4\nny = 3\nlx = 4.0e-3\nly = 3.0e-3\n\n"
    steel = '[substrate]\nmaterial = "steel"\n\n'
    return {
        "file_pressure.toml": grid + steel
        + '[pressure]\nkind = "file"\npath = "h.npy"\n\n[method]\nname = "direct"\n',
        "uniform_disk.toml": grid + "[substrate]\nE = 2.1e11\nnu = 0.3\n\n"
        + '[[coating]]\nE = 4e11\nnu = 0.25\nthickness = 1e-4\ninterface = "frictionless"\n\n'
        + '[[coating]]\nmaterial = "dlc"\nthickness = 2e-6\n\n'
        + '[pressure]\nkind = "uniform_disk"\np = 1e8\na = 1e-3\nsampling = "centre"\n\n'
        + '[method]\nname = "frf-dcfft"\nalpha = 2.0\ng0 = "quadrature"\ng0_tol = 1e-8\n'
        + 'planning = "estimate"\nthreads = 2\nwisdom = "w.fftw"\n',
        "height_map.toml": grid + steel
        + '[contact]\nindenter = "height_map"\npath = "h.csv"\napproach = 1e-7\n'
        + "tolerance = 1e-8\nmax_iterations = 50\n",
        "flat_punch.toml": grid + steel
        + '[contact]\nindenter = "flat_punch"\nradius = 1e-3\nedge_radius = 1e-4\n'
        + 'load = 10.0\nreport_approach = false\nindenter_material = "tungsten_carbide"\n',
        "cylinder.toml": grid + steel
        + '[contact]\nindenter = "cylinder"\nradius = 0.01\nlength = 1e-3\nend_radius = 0.02\n'
        + "load = 5.0\nindenter_E = 6e11\nindenter_nu = 0.22\n",
        "paraboloid.toml": grid + '[substrate]\nmaterial = "peek"\n\n'
        + '[[coating]]\nmaterial = "titanium_nitride"\nthickness = 1e-5\n\n'
        + '[contact]\nindenter = "paraboloid"\nradius = 0.05\nload = 1.0\n\n'
        + '[method]\nname = "frf-split"\n',
    }


def x3p(counts_rows, data_type="L", valid=None, increment="1e-9", inline=False, sizes=None,
        data=None, data_md5=True, deflate=False):
    """A small ISO 25178-72 archive: int32 (or other) points x fastest, MD5 sums (hashlib); the
    points `inline` as <Datum> elements, or other `sizes` (SizeX, SizeY) or `data` than theirs."""
    import hashlib
    import io
    import zipfile
    formats = {"I": "<h", "L": "<i", "F": "<f", "D": "<d"}
    ny, nx = sizes[::-1] if sizes else (len(counts_rows), len(counts_rows[0]))
    if data is None and not inline:
        data = b"".join(struct.pack(formats[data_type], v) for row in counts_rows for v in row)
    link = "<PointDataLink>bindata/data.bin</PointDataLink>"
    if data_md5 and not inline:
        link += "<MD5ChecksumPointData>" + hashlib.md5(data).hexdigest() + "</MD5ChecksumPointData>"
    if valid is not None:
        link += ("<ValidPointsLink>bindata/valid.bin</ValidPointsLink><MD5ChecksumValidPoints>"
                 + hashlib.md5(valid).hexdigest() + "</MD5ChecksumValidPoints>")
    xml = ('<?xml version="1.0" encoding="UTF-8"?>\n<p:ISO5436_2 xmlns:p="http://www.opengps.eu/'
           '2008/ISO5436_2"><Record1><Revision>ISO5436 - 2000</Revision><FeatureType>SUR'
           '</FeatureType><Axes><CX><AxisType>I</AxisType><DataType>D</DataType><Increment>1e-6'
           '</Increment><Offset>0</Offset></CX><CY><AxisType>I</AxisType><DataType>D</DataType>'
           '<Increment>2e-6</Increment><Offset>0</Offset></CY><CZ><AxisType>A</AxisType>'
           f'<DataType>{data_type}</DataType><Increment>{increment}</Increment><Offset>0</Offset>'
           '</CZ></Axes></Record1><Record2><Date>2026-01-01T00:00:00</Date><Creator>corpus'
           '</Creator></Record2><Record3><MatrixDimension>'
           f'<SizeX>{nx}</SizeX><SizeY>{ny}</SizeY><SizeZ>1</SizeZ></MatrixDimension>'
           + ("<DataList>" + "".join(f"<Datum>{v}</Datum>" for row in counts_rows for v in row)
              + "</DataList>" if inline else f"<DataLink>{link}</DataLink>")
           + '</Record3><Record4><ChecksumFile>md5checksum.hex'
           '</ChecksumFile></Record4></p:ISO5436_2>\n').encode()
    out = io.BytesIO()
    with zipfile.ZipFile(out, "w", zipfile.ZIP_STORED) as archive:
        archive.writestr("main.xml", xml)
        archive.writestr("md5checksum.hex", hashlib.md5(xml).hexdigest() + " *main.xml\n")
        if not inline:
            archive.writestr("bindata/data.bin", data,
                             zipfile.ZIP_DEFLATED if deflate else zipfile.ZIP_STORED)
        if valid is not None:
            archive.writestr("bindata/valid.bin", valid)
    return out.getvalue()


def damaged(archive):
    """`archive` with one bit flipped in the last byte of its stored data.bin."""
    at = archive.index(b"bindata/data.bin", archive.index(b"bindata/data.bin") + 1)
    at = archive.rindex(b"PK\3\4", 0, at)
    name_length, extra_length = struct.unpack_from("<HH", archive, at + 26)
    size = struct.unpack_from("<I", archive, at + 18)[0]
    end = at + 30 + name_length + extra_length + size
    return archive[:end - 1] + bytes([archive[end - 1] ^ 0x40]) + archive[end:]


# NetCDF-3 (classic, CDF-1; 64-bit offset, CDF-2) written from its format's grammar (netcdf-c's
# docs, "The NetCDF File Format"): big-endian, names and values padded to 4 bytes.
NC_TYPES = {"b": (1, "b"), "c": (2, "c"), "s": (3, ">h"), "i": (4, ">i"), "f": (5, ">f"),
            "d": (6, ">d")}


def nc_name(name):
    data = name.encode()
    return struct.pack(">i", len(data)) + data + b"\0" * (-len(data) % 4)


def nc_attributes(attributes):
    """(name, value) pairs: str as NC_CHAR, else (type letter, [numbers])."""
    if not attributes:
        return struct.pack(">ii", 0, 0)
    out = struct.pack(">ii", 0x0C, len(attributes))
    for name, value in attributes:
        if isinstance(value, str):
            kind, data, count = 2, value.encode(), len(value.encode())
        else:
            kind, form = NC_TYPES[value[0]]
            data, count = b"".join(struct.pack(form, v) for v in value[1]), len(value[1])
        out += nc_name(name) + struct.pack(">ii", kind, count) + data + b"\0" * (-len(data) % 4)
    return out


def netcdf3(dims, variables, attributes=(), version=1, data=True):
    """dims: (name, length); variables: (name, dim ids, attributes, type letter, values). The
    data follows the header (values, packed, padded), or not at all with data=False."""
    def header(begins):
        out = b"CDF" + bytes([version]) + struct.pack(">i", 0)
        out += struct.pack(">ii", 0x0A, len(dims)) + b"".join(
            nc_name(n) + struct.pack(">i", size) for n, size in dims)
        out += nc_attributes(attributes) + struct.pack(">ii", 0x0B, len(variables))
        for (name, ids, atts, kind, values), begin in zip(variables, begins):
            count = 1
            for i in ids:
                count *= dims[i][1]
            size = count * struct.calcsize(NC_TYPES[kind][1])
            size = size + -size % 4 if size + -size % 4 < 2**32 else 2**32 - 1  # CDF-2's rule
            out += nc_name(name) + struct.pack(">i", len(ids)) + b"".join(
                struct.pack(">i", i) for i in ids) + nc_attributes(atts)
            out += struct.pack(">iI", NC_TYPES[kind][0], size)
            out += struct.pack(">I" if version == 1 else ">Q", begin)
        return out
    blocks = [v[4] if v[3] == "c" else b"".join(struct.pack(NC_TYPES[v[3]][1], x) for x in v[4])
              for v in variables]
    blocks = [b + b"\0" * (-len(b) % 4) for b in blocks]
    begins, at = [], len(header([0] * len(variables)))
    for block in blocks:
        begins.append(at)
        at += len(block)
    return header(begins) + (b"".join(blocks) if data else b"")


def netcdf_seeds():
    """NetCDF-3 files of the layouts the reader takes, default-filled heights and a header
    declaring 23000 x 23000 heights without them. No NetCDF-4 (HDF5) files: fuzz_topography
    passes only NetCDF-3 input to the reader (fuzz/findings/README.md)."""
    axes = [("x", 3), ("y", 2)]
    coordinates = [("x", [0], [("length", ("d", [3e-6])), ("length_unit", "m"),
                                ("periodic", ("i", [1]))], "d", [0, 1e-6, 2e-6]),
                   ("y", [1], [("length", ("d", [2e-6])), ("unit", "um"),
                                ("periodic", ("i", [1]))], "d", [0, 1e-6])]
    fill = 9.969209968386869e36
    seeds = {
        "classic.nc": netcdf3(axes, coordinates + [
            ("heights", [0, 1], [("units", "m"), ("_FillValue", ("d", [-1.0]))], "d",
             [1e-9, 2e-9, 3e-9, 4e-9, -1.0, 6e-9])], [("instrument", "corpus")]),
        "yx_packed.nc": netcdf3(list(reversed(axes)), [
            ("heights", [0, 1], [("scale_factor", ("f", [0.5])), ("add_offset", ("d", [1.0])),
                                 ("missing_value", ("s", [-1, -2])), ("units", "nm")],
             "s", [1, 2, 3, -1, 5, -2])], version=2),
        "default_fill.nc": netcdf3(axes, [("heights", [0, 1], [], "f",
                                           [1.0, 2.0, 3.0, fill, fill, fill])]),
        # Padded with zeros: netcdf-c's in-memory open refuses some files of under 112 bytes.
        "declared_23000.nc": netcdf3([("x", 23000), ("y", 23000)],
                                     [("heights", [0, 1], [], "d", [])], version=2,
                                     data=False).ljust(512, b"\0"),
        "text_heights.nc": netcdf3(axes, [("heights", [0, 1], [], "c", b"abcdef")]).ljust(128,
                                                                                         b"\0"),
    }
    return seeds


def topography_seeds():
    """The first byte chooses the format (fuzz_topography.cpp): 0 X3P, 1 SDF, 2 x y z rows,
    3 NetCDF; 4 to 7 the same with missing points filled."""
    sdf_header = ("aISO-1.0\r\nManufacID = corpus\r\nCreateDate = 010120260000\r\n"
                  "ModDate = 010120260000\r\nNumPoints = 3\r\nNumProfiles = 2\r\n"
                  "Xscale = 1.0E-6\r\nYscale = 2.0E-6\r\nZscale = 1.0E-9\r\n"
                  "Zresolution = -1\r\nCompression = 0\r\nDataType = {}\r\nCheckType = 0\r\n"
                  "NumDataSet = 1\r\nNanPresent = 0\r\n*\r\n")
    binary = (b"bISO-1.0" + b"corpus".ljust(10, b"\0") + b"010120260000" + b"010120260000"
              + struct.pack("<HHdddd", 3, 2, 1e-6, 2e-6, 1e-9, -1.0) + bytes([0, 5, 0])
              + b"".join(struct.pack("<h", v) for v in (1, 2, 3, 4, 5, -32768)))
    return {
        "int32.x3p": b"\0" + x3p([[1, 2, 3], [4, 5, 6]]),
        "int16_valid.x3p": b"\0" + x3p([[1, 2, 3, 4], [5, 6, 7, 8]], "I", valid=bytes([0xEF])),
        "double.x3p": b"\0" + x3p([[0.5, 1.5], [2.5, float("nan")]], "D", increment="1"),
        "inline.x3p": b"\0" + x3p([[1.5, 2.5, ""], [3.5, 4.5, 5.5]], "D", inline=True),
        # Bombs: far more points declared than held, a data.bin of 1 MiB (deflated to 1 kB) for
        # 2 x 2 points, and a damaged data.bin without an MD5 (only its CRC-32 tells).
        "declared_inline.x3p": b"\0" + x3p([[1, 2, 3]], "D", inline=True, sizes=(23000, 23000)),
        "unpacks_large.x3p": b"\0" + x3p([[1, 2], [3, 4]], data=bytes(1 << 20), deflate=True),
        "damaged_crc.x3p": b"\0" + damaged(x3p([[1, 2, 3], [4, 5, 6]], data_md5=False)),
        "declared.sdf": b"\1" + (sdf_header.replace("= 3\r", "= 23000\r").replace("= 2\r", "= 23000\r")
                                 .format(7) + "1 2 3\r\n*\r\n").encode(),
        "double.sdf": b"\1" + (sdf_header.format(7) + "1.5 2.5 3.5\r\n4.5 5.5 BAD\r\n*\r\n").encode(),
        "int16.sdf": b"\1" + (sdf_header.format(5) + "1 2 3 4 5 -32768\r\n*\r\n").encode(),
        "binary.sdf": b"\1" + binary,
        "mountainsmap.sdf": b"\1" + (REPO / "tests" / "data" / "topography"
                                       / "mm11_iso1_ascii_int32.sdf").read_bytes(),
        "rows.xyz": b"\2x y z\n0 0 1\n1 0 2\n0 1 3\n1 1 nan\n",
        "shuffled.xyz": b"\6# comment\n1.0,0.5,3\n0.0,0.5,4\n0.0,0.0,1\n1.0,0.0,2\n",
    }


def write(folder, files):
    target = ROOT / "corpus" / folder
    shutil.rmtree(target, ignore_errors=True)
    target.mkdir(parents=True)
    for name, content in files.items():
        data = content if isinstance(content, bytes) else content.encode()
        (target / name).write_bytes(data)


def main():
    scenes = scene_seeds()
    for example in sorted((REPO / "examples" / "scenes").glob("*.toml")):
        scenes["example_" + example.name] = example.read_bytes()
    write("fuzz_scene", scenes)
    write("fuzz_npy", npy_seeds())
    write("fuzz_csv", csv_seeds())
    seeds = topography_seeds()
    for k, (name, data) in enumerate(netcdf_seeds().items()):
        seeds[name] = bytes([3 + 4 * (k % 2)]) + data
    write("fuzz_topography", seeds)


if __name__ == "__main__":
    main()
