# SPDX-License-Identifier: Zlib
# Fixture of core.layering_rejects: a tree with one include against the module graph of each kind.
set(BTFRACTURE_PUBLIC_HEADERS btFracture.h core/Public.h)
