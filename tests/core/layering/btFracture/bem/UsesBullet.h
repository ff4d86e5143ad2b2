// SPDX-License-Identifier: Zlib
#pragma once
#include <btBulletDynamicsCommon.h>
#include <btFracture/core/Private.h>
