#pragma once
// The mesh module's vector helpers are the library's one set (tissue/core/vec_math.h); this
// header only brings them into the module's detail namespace.

#include "tissue/core/vec_math.h"

namespace tissue::mesh::detail {

using tissue::cross;
using tissue::dot;
using tissue::isFinite;
using tissue::length;
using tissue::normalizeOr;

}  // namespace tissue::mesh::detail
