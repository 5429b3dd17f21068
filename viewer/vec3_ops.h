#pragma once
/// \file
/// The viewer's vector operations on tissue::Float3 are the library's one set
/// (tissue/core/vec_math.h), found from namespace tissue::viewer by ordinary lookup.

#include "tissue/core/vec_math.h"
