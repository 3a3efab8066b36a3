# Imported target OpenFOAM::finiteVolume: the Debian v1912 libraries in
# /usr/lib with the headers that etc/bootstrap extracted from Debian's source
# package (WSF_FOAM_SRC). Flags and link order as the libraries were built
# (OpenFOAM's wmake rules linux64Gcc: -m64, WM_DP, WM_LABEL_SIZE=32).
set(WSF_FOAM_SRC "$ENV{WSF_FOAM_SRC}" CACHE PATH "OpenFOAM v1912 source tree with lnInclude folders")
if(NOT WSF_FOAM_SRC)
    set(WSF_FOAM_SRC "/opt/wavyShearFoam/OpenFOAM-v1912" CACHE PATH "" FORCE)
endif()
if(NOT EXISTS "${WSF_FOAM_SRC}/src/OpenFOAM/lnInclude/fvCFD.H" AND
   NOT EXISTS "${WSF_FOAM_SRC}/src/finiteVolume/lnInclude/fvCFD.H")
    message(FATAL_ERROR "OpenFOAM headers not found in WSF_FOAM_SRC=${WSF_FOAM_SRC}: run etc/bootstrap")
endif()
set(WSF_FOAM_ETC "/usr/share/openfoam" CACHE PATH "WM_PROJECT_DIR for running OpenFOAM programs")

add_library(OpenFOAM_finiteVolume INTERFACE)
add_library(OpenFOAM::finiteVolume ALIAS OpenFOAM_finiteVolume)
foreach(dir OpenFOAM OSspecific/POSIX finiteVolume meshTools lagrangian/basic fileFormats surfMesh)
    target_include_directories(OpenFOAM_finiteVolume SYSTEM INTERFACE "${WSF_FOAM_SRC}/src/${dir}/lnInclude")
endforeach()
target_compile_definitions(OpenFOAM_finiteVolume INTERFACE
    WM_DP WM_LABEL_SIZE=32 NoRepository OPENFOAM=1912)
target_compile_options(OpenFOAM_finiteVolume INTERFACE
    -m64 -ftemplate-depth-100 -Wno-deprecated-declarations -Wno-old-style-cast)
target_link_options(OpenFOAM_finiteVolume INTERFACE
    -Wl,--add-needed -Wl,--no-as-needed)
target_link_libraries(OpenFOAM_finiteVolume INTERFACE
    lagrangian finiteVolume meshTools OpenFOAM dl m)
