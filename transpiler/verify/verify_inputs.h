// verify's input synthesis: the vertex data, buffers, images, samplers and push constants a module
// declares, generated from its own reflection (no shader-specific knowledge), and the eye
// parameters set where the transpiled module reads them. The original and the transpiled stages
// get exactly the same data for the resources they share.
#pragma once

#include "core/result.h"
#include "transpiler/verify/stereo_verify.h"

#include <string>

namespace stereoshift::harness {

// Vertex data for every user input of a vertex shader: `count` vertices (see verify_inputs.cpp).
// An empty buffer when the shader has no vertex inputs; the error when one has a type the harness
// cannot feed.
Result<VertexBuffer> buildVertices(const spirv::Module& m, uint32_t count);

// Buffers, images, samplers and push constants of one module (merged across stages by the caller:
// a (set, binding) already present keeps its data).
Status buildResources(const spirv::Module& m, PipelineInputs* in);

// Writes eyeSign / separation / convergence where the transpiled module reads them (block members
// of a uniform block or push constants, or specialization constants, or 3Dmigoto's texture): whether
// eyeSign itself was among them; the error when it has none.
Result<bool> applyEyeParameters(const spirv::Module& m, const VerifySettings& s, float eyeSign, PipelineInputs* in);

// Bytes of the module's push-constant block, as the generated data fill it.
uint32_t pushConstantBytes(const spirv::Module& m);

}  // namespace stereoshift::harness
