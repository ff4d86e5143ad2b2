# SPDX-License-Identifier: Zlib
# Finds btFracture's dependencies as Debian 12 ships them. Used by the build and by the
# installed package (btFractureConfig.cmake), so an app re-finds them on its own machine.
#
# In:  BTFRACTURE_BULLET_DOUBLE (ON: Debian's *-float64 Bullet + BT_USE_DOUBLE_PRECISION)
# Out: btFracture::Bullet        INTERFACE: Bullet headers (SYSTEM), core libraries, precision define
#      btFracture::BulletExtras  INTERFACE: BulletWorldImporter, BulletFileLoader, GIMPACTUtils, HACD
#      Eigen3::Eigen, ccd, TBB::tbb, Boost::boost, OpenVDB::openvdb, nlohmann_json::nlohmann_json,
#      PNG::PNG (libpng: the runner's preview images)
include_guard(GLOBAL)

find_package(Eigen3 3.4 REQUIRED NO_MODULE)
find_package(ccd REQUIRED)
find_package(TBB REQUIRED)
find_package(Boost REQUIRED)
find_package(nlohmann_json 3.10 REQUIRED)
find_package(OpenMP REQUIRED COMPONENTS CXX)
find_package(PNG REQUIRED)

# OpenVDB ships only a Find module, in its own cmake folder.
if(NOT TARGET OpenVDB::openvdb)
  find_path(BTFRACTURE_OPENVDB_MODULE_DIR FindOpenVDB.cmake
            PATHS /usr/lib/${CMAKE_LIBRARY_ARCHITECTURE}/cmake/OpenVDB /usr/lib/cmake/OpenVDB
                  /usr/local/lib/cmake/OpenVDB
            DOC "Folder holding OpenVDB's FindOpenVDB.cmake")
  if(NOT BTFRACTURE_OPENVDB_MODULE_DIR)
    message(FATAL_ERROR "btFracture: FindOpenVDB.cmake not found; install libopenvdb-dev")
  endif()
  list(APPEND CMAKE_MODULE_PATH "${BTFRACTURE_OPENVDB_MODULE_DIR}")
  find_package(OpenVDB REQUIRED)
endif()

# Bullet: Debian's BulletConfig.cmake has broken relative paths, so find the pieces directly.
if(BTFRACTURE_BULLET_DOUBLE)
  set(_btf_bullet_suffix "-float64")
else()
  set(_btf_bullet_suffix "")
endif()
if(NOT TARGET btFracture::Bullet)
  find_path(BTFRACTURE_BULLET_INCLUDE_DIR btBulletDynamicsCommon.h PATH_SUFFIXES bullet
            DOC "Bullet's header folder")
  if(NOT BTFRACTURE_BULLET_INCLUDE_DIR)
    message(FATAL_ERROR "btFracture: Bullet headers not found; install libbullet-dev")
  endif()
  set(_btf_bullet_core "")
  foreach(_lib BulletDynamics BulletCollision LinearMath)
    find_library(BTFRACTURE_${_lib}${_btf_bullet_suffix}_LIBRARY NAMES ${_lib}${_btf_bullet_suffix})
    if(NOT BTFRACTURE_${_lib}${_btf_bullet_suffix}_LIBRARY)
      message(FATAL_ERROR "btFracture: lib${_lib}${_btf_bullet_suffix} not found; install libbullet-dev")
    endif()
    list(APPEND _btf_bullet_core "${BTFRACTURE_${_lib}${_btf_bullet_suffix}_LIBRARY}")
  endforeach()
  add_library(btFracture::Bullet INTERFACE IMPORTED)
  set_target_properties(btFracture::Bullet PROPERTIES
    INTERFACE_INCLUDE_DIRECTORIES "${BTFRACTURE_BULLET_INCLUDE_DIR}"
    INTERFACE_SYSTEM_INCLUDE_DIRECTORIES "${BTFRACTURE_BULLET_INCLUDE_DIR}"
    INTERFACE_LINK_LIBRARIES "${_btf_bullet_core}")
  if(BTFRACTURE_BULLET_DOUBLE)
    set_property(TARGET btFracture::Bullet PROPERTY INTERFACE_COMPILE_DEFINITIONS BT_USE_DOUBLE_PRECISION)
  endif()

  set(_btf_bullet_extras "")
  foreach(_lib BulletWorldImporter BulletFileLoader GIMPACTUtils HACD)
    find_library(BTFRACTURE_${_lib}${_btf_bullet_suffix}_LIBRARY NAMES ${_lib}${_btf_bullet_suffix})
    if(NOT BTFRACTURE_${_lib}${_btf_bullet_suffix}_LIBRARY)
      message(FATAL_ERROR "btFracture: lib${_lib}${_btf_bullet_suffix} not found; install libbullet-extras-dev")
    endif()
    list(APPEND _btf_bullet_extras "${BTFRACTURE_${_lib}${_btf_bullet_suffix}_LIBRARY}")
  endforeach()
  add_library(btFracture::BulletExtras INTERFACE IMPORTED)
  set_target_properties(btFracture::BulletExtras PROPERTIES
    INTERFACE_INCLUDE_DIRECTORIES "${BTFRACTURE_BULLET_INCLUDE_DIR}"
    INTERFACE_SYSTEM_INCLUDE_DIRECTORIES "${BTFRACTURE_BULLET_INCLUDE_DIR}"
    INTERFACE_LINK_LIBRARIES "${_btf_bullet_extras};btFracture::Bullet")
endif()
