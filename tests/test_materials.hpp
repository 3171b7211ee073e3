#pragma once
// The materials most tests share: a steel and a TiN coating (E [Pa], nu). Defined once here, so
// that the test files of one program can be compiled together (unity builds).
#include "materials/material.hpp"

namespace {

const coatfft::Material steel(210e9, 0.3);
const coatfft::Material tin(400e9, 0.25);

}  // namespace
