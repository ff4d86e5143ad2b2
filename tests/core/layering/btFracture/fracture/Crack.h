// SPDX-License-Identifier: Zlib
#pragma once
#include <btFracture/bem/UsesBullet.h>
