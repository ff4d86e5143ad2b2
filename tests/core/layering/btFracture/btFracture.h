// SPDX-License-Identifier: Zlib
#pragma once
#include <btFracture/core/Public.h>
