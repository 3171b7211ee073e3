"""coatfft: surface displacements and contact of coated and layered elastic bodies.

Fields are float64 numpy arrays of shape (ny, nx), C order, row j at y_j (as the .npy files of
the ``coatfft`` program); every quantity is in SI units (m, Pa, N). The functions and classes
are those of the C++ library; docs/python.md describes each.
"""
from ._coatfft import (
    ContactResult,
    Coating,
    Frf,
    Grid,
    LayerStack,
    Material,
    Operator,
    TabulatedFrf,
    UserFrf,
    __version__,
    frf,
    hankel_displacement,
    hertz_displacement,
    hertz_pressure,
    make_operator,
    material,
    material_names,
    run_scene,
    solve_contact,
    stresses,
    uniform_disk_displacement,
    uniform_disk_pressure,
    validate_frf,
    von_mises,
)

__all__ = [
    "ContactResult",
    "Coating",
    "Frf",
    "Grid",
    "LayerStack",
    "Material",
    "Operator",
    "TabulatedFrf",
    "UserFrf",
    "__version__",
    "frf",
    "hankel_displacement",
    "hertz_displacement",
    "hertz_pressure",
    "make_operator",
    "material",
    "material_names",
    "run_scene",
    "solve_contact",
    "stresses",
    "uniform_disk_displacement",
    "uniform_disk_pressure",
    "validate_frf",
    "von_mises",
]
