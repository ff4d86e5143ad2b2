// SPDX-License-Identifier: Zlib
#pragma once
#include <btFracture/core/Private.h>
