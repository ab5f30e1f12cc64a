// The files a render of a scene reads, so that no output of the render can
// replace one of them.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "facet/runtime/scene.h"

namespace facet::runtime {

// A file the render reads, and what it is to the scene, for the error.
struct SceneInput {
  std::string path;
  std::string what;  // "a texture of the scene"
};

// The scene file, and every mesh (with a glTF mesh's buffers), shader,
// texture and environment image it names.
std::vector<SceneInput> scene_inputs(const std::string& scene_path, const Scene& scene);

// The error for two outputs that are one file (one would replace the
// other), else for an output that is the same file as an input (compared by
// device and inode, so another spelling or a hard link counts): writing the
// image would destroy the input. An output that does not exist yet is no
// input. `program` begins the message ("facet render").
std::optional<std::string> output_clash(const std::string& program, const std::vector<std::string>& outputs,
                                        const std::vector<SceneInput>& inputs);

}  // namespace facet::runtime
