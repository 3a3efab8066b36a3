# For the tests that compile against OpenFOAM and the project's wmake-built
# libraries (the libraries themselves are built by wmake, not here).
#
# OpenFOAM::finiteVolume: OpenFOAM's headers ($FOAM_SRC/*/lnInclude: your own
# installation, or the tree etc/bootstrap prepared from Debian's source
# package) and libraries ($FOAM_LIBBIN, or Debian's /usr/lib), with the
# definitions and link flags of wmake's linux64Gcc rules.
# wsf::ambientFlow, wsf::suspensionFoam: libambientFlow and libsuspensionFoam
# from $FOAM_USER_LIBBIN, with their lnInclude folders.
set(WSF_FOAM_SRC "$ENV{FOAM_SRC}" CACHE PATH "OpenFOAM's src/ with lnInclude folders (FOAM_SRC)")
set(WSF_FOAM_LIBBIN "$ENV{FOAM_LIBBIN}" CACHE PATH "OpenFOAM's libraries (FOAM_LIBBIN)")
set(WSF_FOAM_ETC "$ENV{WM_PROJECT_DIR}" CACHE PATH "WM_PROJECT_DIR for running OpenFOAM programs")
if(NOT EXISTS "${WSF_FOAM_SRC}/finiteVolume/lnInclude/fvCFD.H")
    message(FATAL_ERROR "OpenFOAM headers not found in FOAM_SRC=${WSF_FOAM_SRC}: run etc/bootstrap and source etc/bashrc")
endif()

add_library(OpenFOAM_finiteVolume INTERFACE)
add_library(OpenFOAM::finiteVolume ALIAS OpenFOAM_finiteVolume)
foreach(dir OpenFOAM OSspecific/POSIX finiteVolume meshTools lagrangian/basic fileFormats surfMesh)
    target_include_directories(OpenFOAM_finiteVolume SYSTEM INTERFACE "${WSF_FOAM_SRC}/${dir}/lnInclude")
endforeach()
# The definitions wmake gives (wmake/rules/General/general), from the
# environment the libraries were built in
set(WSF_FOAM_PRECISION "$ENV{WM_PRECISION_OPTION}" CACHE STRING "WM_PRECISION_OPTION (DP, SP)")
set(WSF_FOAM_LABEL_SIZE "$ENV{WM_LABEL_SIZE}" CACHE STRING "WM_LABEL_SIZE (32, 64)")
set(WSF_FOAM_API "$ENV{FOAM_API}" CACHE STRING "FOAM_API (1912)")
if(NOT WSF_FOAM_PRECISION OR NOT WSF_FOAM_LABEL_SIZE OR NOT WSF_FOAM_API)
    message(FATAL_ERROR "WM_PRECISION_OPTION, WM_LABEL_SIZE or FOAM_API unset: source etc/bashrc (or your OpenFOAM environment) first")
endif()
target_compile_definitions(OpenFOAM_finiteVolume INTERFACE
    WM_${WSF_FOAM_PRECISION} WM_LABEL_SIZE=${WSF_FOAM_LABEL_SIZE}
    NoRepository OPENFOAM=${WSF_FOAM_API})
target_compile_options(OpenFOAM_finiteVolume INTERFACE
    -m64 -ftemplate-depth-100 -Wno-deprecated-declarations -Wno-old-style-cast)
target_link_directories(OpenFOAM_finiteVolume INTERFACE "${WSF_FOAM_LIBBIN}")
target_link_options(OpenFOAM_finiteVolume INTERFACE
    -Wl,--add-needed -Wl,--no-as-needed)
target_link_libraries(OpenFOAM_finiteVolume INTERFACE
    lagrangian finiteVolume meshTools OpenFOAM dl m)

# The project's wmake-built libraries (an INTERFACE target: the lnInclude
# folders and the libraries appear only when wmake has run)
foreach(lib ambientFlow suspensionFoam)
    add_library(wsf_${lib} INTERFACE)
    add_library(wsf::${lib} ALIAS wsf_${lib})
    target_include_directories(wsf_${lib} INTERFACE "${PROJECT_SOURCE_DIR}/src/${lib}/lnInclude")
    target_link_libraries(wsf_${lib} INTERFACE "${WSF_LIBBIN}/lib${lib}.so")
endforeach()
target_link_libraries(wsf_ambientFlow INTERFACE suspension OpenFOAM::finiteVolume)
target_link_libraries(wsf_suspensionFoam INTERFACE wsf::ambientFlow)
