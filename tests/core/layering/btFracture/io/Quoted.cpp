// SPDX-License-Identifier: Zlib
#include "Quoted.h"
#include <png.h>
#include <nlohmann/json.hpp>
