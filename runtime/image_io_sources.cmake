# The image reader's sources for FACET_IMAGE_IO (oiio or png), in one place
# for facet_render and the fuzz_image target: the decoder and the header
# walks that run before it.
set(FACET_IMAGE_IO_DIR ${CMAKE_CURRENT_LIST_DIR}/src/image_io)
if(FACET_IMAGE_IO STREQUAL "oiio")
  set(FACET_IMAGE_IO_SOURCES ${FACET_IMAGE_IO_DIR}/oiio.cpp ${FACET_IMAGE_IO_DIR}/exr_header.cpp
    ${FACET_IMAGE_IO_DIR}/jpeg_header.cpp ${FACET_IMAGE_IO_DIR}/png_header.cpp)
elseif(FACET_IMAGE_IO STREQUAL "png")
  set(FACET_IMAGE_IO_SOURCES ${FACET_IMAGE_IO_DIR}/png.cpp ${FACET_IMAGE_IO_DIR}/png_header.cpp)
else()
  message(FATAL_ERROR "FACET_IMAGE_IO must be oiio or png, not '${FACET_IMAGE_IO}'")
endif()
