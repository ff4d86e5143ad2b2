// SPDX-License-Identifier: Zlib
#include <openvdb/openvdb.h>
