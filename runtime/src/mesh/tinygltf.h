// tinygltf as facet builds it: no stb_image (facet loads textures itself),
// no reading of image files. Every file that includes tinygltf includes it
// through this header, since the defines change the TinyGLTF class.
#pragma once

#define TINYGLTF_NO_STB_IMAGE
#define TINYGLTF_NO_STB_IMAGE_WRITE
#define TINYGLTF_NO_EXTERNAL_IMAGE
#include <tiny_gltf.h>
