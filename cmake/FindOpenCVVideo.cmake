# Finds the parts of OpenCV that video decoding and encoding need (Debian's libopencv-videoio-dev,
# libopencv-imgproc-dev and the libopencv-core-dev they bring), without the libopencv-dev
# metapackage and its CMake config. Defines the imported target OpenCV::Video.
find_path(OpenCVVideo_INCLUDE_DIR opencv2/videoio.hpp PATH_SUFFIXES opencv4)
find_library(OpenCVVideo_CORE_LIBRARY opencv_core)
find_library(OpenCVVideo_IMGPROC_LIBRARY opencv_imgproc)
find_library(OpenCVVideo_VIDEOIO_LIBRARY opencv_videoio)
include(FindPackageHandleStandardArgs)
find_package_handle_standard_args(OpenCVVideo
  REQUIRED_VARS OpenCVVideo_INCLUDE_DIR OpenCVVideo_VIDEOIO_LIBRARY OpenCVVideo_IMGPROC_LIBRARY OpenCVVideo_CORE_LIBRARY)
if(OpenCVVideo_FOUND AND NOT TARGET OpenCV::Video)
  add_library(OpenCV::Video INTERFACE IMPORTED)
  set_target_properties(OpenCV::Video PROPERTIES
    INTERFACE_INCLUDE_DIRECTORIES "${OpenCVVideo_INCLUDE_DIR}"
    INTERFACE_LINK_LIBRARIES "${OpenCVVideo_VIDEOIO_LIBRARY};${OpenCVVideo_IMGPROC_LIBRARY};${OpenCVVideo_CORE_LIBRARY}")
endif()
