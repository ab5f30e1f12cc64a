// tinygltf's implementation, compiled here from Debian's header (rather
// than linking its shared library) so that it is built with facet's flags,
// sanitizers and fuzzing instrumentation included (mesh/tinygltf.h has the
// configuration).
#define TINYGLTF_IMPLEMENTATION
#include "mesh/tinygltf.h"
