// What verify does to its own copies of the modules before they run on the harness's Vulkan
// device, original and transpiled alike, so that both run and are compared on equal terms:
// push constants over the device limit as a uniform buffer, double vertex inputs fed as floats,
// the same Invariant outputs in both, the view index bound per view (multiview), the eye route
// made a captured output (instanced), D3D register classes and OpenGL binding classes given
// separate binding ranges; and the device features a module needs. None of it is part of a
// conversion's output.
#pragma once

#include "core/result.h"
#include "transpiler/verify/stereo_verify.h"

#include <string>

namespace stereoshift::harness {

VkShaderStageFlagBits toVk(spv::ExecutionModel model);

// Whether two OpenGL binding classes (texture units, uniform blocks, storage blocks, images, atomic
// counters) use one (set, binding): legal only in OpenGL, where each class numbers its own, so GLSL
// that glslang also accepts with Vulkan rules is OpenGL GLSL after all (verify_stages.cpp).
bool sharesBindingAcrossOpenGLClasses(const spirv::Module& m);

// A push-constant block larger than the device allows becomes a uniform buffer at (set, 0).
void pushConstantsToUniformBuffer(spirv::Module& m, uint32_t set);

// The device features a module's capabilities need; empty when the device has them all.
std::string missingFeature(const spirv::Module& m, const VkPhysicalDeviceFeatures& f);

// Double-precision vertex inputs become float inputs whose loads are converted to double.
void feedDoubleInputsAsFloats(spirv::Module& m);

// Vertices per input primitive of a geometry shader, and the list topology that feeds it.
uint32_t geometryInput(const spirv::Module& geometry, VkPrimitiveTopology* topology);

// Marks Invariant in `original` the outputs `transpiled` marks Invariant.
void matchInvariance(spirv::Module& original, const spirv::Module& transpiled);

// Multiview: the module's reads of the view index read `view` as a constant; the error when the
// view index is used other than by a load.
Status bindViewIndex(spirv::Module& m, uint32_t view);

// Instanced: the built-in the vertex stage writes the eye to becomes an ordinary output the capture
// reads; returns its name, empty when the shader writes no such built-in.
std::string exposeEyeRoute(spirv::Module& m, EyeRoute route);

}  // namespace stereoshift::harness
