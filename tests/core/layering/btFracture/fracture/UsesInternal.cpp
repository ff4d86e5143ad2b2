// SPDX-License-Identifier: Zlib
#include <btFracture/geometry/internal/Grids.h>
