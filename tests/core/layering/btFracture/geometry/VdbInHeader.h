// SPDX-License-Identifier: Zlib
#pragma once
#include <openvdb/openvdb.h>
