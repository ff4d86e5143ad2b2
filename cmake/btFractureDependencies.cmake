# SPDX-License-Identifier: Zlib
# Finds btFracture's dependencies as Debian 12 ships them. Used by the build and by the
# installed package (btFractureConfig.cmake), so an app re-finds them on its own machine.
#
# In:  BTFRACTURE_BULLET_DOUBLE (ON: Debian's *-float64 Bullet + BT_USE_DOUBLE_PRECISION)
#      BTFRACTURE_IO_DEPENDENCIES (ON in the build: also what btFracture::io needs; the
#      installed package, which has no io, leaves it off)
# Out: btFracture::Bullet          INTERFACE: Bullet headers (SYSTEM), core libraries, precision define
#      btFracture::BulletHACD      INTERFACE: Bullet's HACD (convex decomposition)
#      Eigen3::Eigen, ccd, TBB::tbb, Boost::boost, OpenVDB::openvdb, OpenMP::OpenMP_CXX
#      with BTFRACTURE_IO_DEPENDENCIES:
#      btFracture::BulletImporter  INTERFACE: BulletWorldImporter, BulletFileLoader (FractureRB files)
#      nlohmann_json::nlohmann_json (scene files, run.json), PNG::PNG (preview images)
include_guard(GLOBAL)

find_package(Eigen3 3.4 REQUIRED NO_MODULE)
find_package(ccd REQUIRED)
find_package(TBB REQUIRED)
find_package(Boost REQUIRED)
find_package(OpenMP REQUIRED COMPONENTS CXX)
if(BTFRACTURE_IO_DEPENDENCIES)
  find_package(nlohmann_json 3.10 REQUIRED)
  find_package(PNG REQUIRED)
endif()

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
# btfracture_bullet_target(<target> <Debian package> <libraries...>): an INTERFACE target over
# Bullet libraries of this precision, with Bullet's headers as SYSTEM headers.
function(btfracture_bullet_target target package)
  set(libraries "")
  foreach(_lib ${ARGN})
    find_library(BTFRACTURE_${_lib}${_btf_bullet_suffix}_LIBRARY NAMES ${_lib}${_btf_bullet_suffix})
    if(NOT BTFRACTURE_${_lib}${_btf_bullet_suffix}_LIBRARY)
      message(FATAL_ERROR "btFracture: lib${_lib}${_btf_bullet_suffix} not found; install ${package}")
    endif()
    list(APPEND libraries "${BTFRACTURE_${_lib}${_btf_bullet_suffix}_LIBRARY}")
  endforeach()
  add_library(${target} INTERFACE IMPORTED)
  set_target_properties(${target} PROPERTIES
    INTERFACE_INCLUDE_DIRECTORIES "${BTFRACTURE_BULLET_INCLUDE_DIR}"
    INTERFACE_SYSTEM_INCLUDE_DIRECTORIES "${BTFRACTURE_BULLET_INCLUDE_DIR}"
    INTERFACE_LINK_LIBRARIES "${libraries}")
endfunction()

if(NOT TARGET btFracture::Bullet)
  find_path(BTFRACTURE_BULLET_INCLUDE_DIR btBulletDynamicsCommon.h PATH_SUFFIXES bullet
            DOC "Bullet's header folder")
  if(NOT BTFRACTURE_BULLET_INCLUDE_DIR)
    message(FATAL_ERROR "btFracture: Bullet headers not found; install libbullet-dev")
  endif()
  btfracture_bullet_target(btFracture::Bullet libbullet-dev BulletDynamics BulletCollision LinearMath)
  if(BTFRACTURE_BULLET_DOUBLE)
    set_property(TARGET btFracture::Bullet PROPERTY INTERFACE_COMPILE_DEFINITIONS BT_USE_DOUBLE_PRECISION)
  endif()
  btfracture_bullet_target(btFracture::BulletHACD libbullet-extras-dev HACD)
  target_link_libraries(btFracture::BulletHACD INTERFACE btFracture::Bullet)
endif()
if(BTFRACTURE_IO_DEPENDENCIES AND NOT TARGET btFracture::BulletImporter)
  btfracture_bullet_target(btFracture::BulletImporter libbullet-extras-dev BulletWorldImporter BulletFileLoader)
  target_link_libraries(btFracture::BulletImporter INTERFACE btFracture::Bullet)
endif()
