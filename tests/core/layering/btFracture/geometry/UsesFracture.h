// SPDX-License-Identifier: Zlib
#pragma once
#include <btFracture/fracture/Crack.h>
