# Finds OpenCV's core and ml modules from Debian's small libopencv-core-dev / libopencv-ml-dev
# packages (about 4 MB). Those ship no CMake config; the full libopencv-dev has one but pulls in
# ~200 packages (GUI, video, codecs) that a Qt-free numeric core never uses.
# Defines OpenCV::core and OpenCV::ml.
find_path(OpenCVCore_INCLUDE_DIR opencv2/core.hpp PATH_SUFFIXES opencv4)
find_library(OpenCVCore_CORE_LIBRARY opencv_core)
find_library(OpenCVCore_ML_LIBRARY opencv_ml)

include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(OpenCVCore
  REQUIRED_VARS OpenCVCore_INCLUDE_DIR OpenCVCore_CORE_LIBRARY OpenCVCore_ML_LIBRARY)

if(OpenCVCore_FOUND AND NOT TARGET OpenCV::core)
  add_library(OpenCV::core UNKNOWN IMPORTED)
  set_target_properties(OpenCV::core PROPERTIES
    IMPORTED_LOCATION "${OpenCVCore_CORE_LIBRARY}"
    INTERFACE_INCLUDE_DIRECTORIES "${OpenCVCore_INCLUDE_DIR}")
  add_library(OpenCV::ml UNKNOWN IMPORTED)
  set_target_properties(OpenCV::ml PROPERTIES
    IMPORTED_LOCATION "${OpenCVCore_ML_LIBRARY}"
    INTERFACE_LINK_LIBRARIES OpenCV::core)
endif()
mark_as_advanced(OpenCVCore_INCLUDE_DIR OpenCVCore_CORE_LIBRARY OpenCVCore_ML_LIBRARY)
