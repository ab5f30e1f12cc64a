// A glTF material as the properties and keywords of Unity's Standard shader
// (metallic setup): what a scene object with "gltf_materials": true gets on
// top of its own material (docs/scene-format.md, "glTF meshes").
#pragma once

#include <string>

#include "facet/result.h"
#include "facet/runtime/gltf.h"
#include "facet/runtime/scene.h"

namespace facet::runtime {

// `base` (the object's material) plus the glTF material `index` of the file
// (-1: glTF's default material, which GltfMaterial's defaults are):
// _Color, _MainTex, _Metallic, _Glossiness, _MetallicGlossMap (+ _GlossMapScale
// and the _METALLICGLOSSMAP keyword), _BumpMap (+ _BumpScale, _NORMALMAP),
// _EmissionColor and _EmissionMap (+ _EMISSION). A property or keyword the
// scene sets itself wins; the added properties are skipped where the shader
// does not declare them (SceneProperty::if_declared). The error names the
// glTF value ("materials[0].normalTexture.texCoord: ...").
Result<SceneMaterial, std::string> with_gltf_material(const SceneMaterial& base, const GltfMaterial& material,
                                                      int index);

}  // namespace facet::runtime
