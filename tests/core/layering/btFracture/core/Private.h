// SPDX-License-Identifier: Zlib
#pragma once
#include <vector>
