// The one rule that tells a shader's stage from its path and text (transpiler/source/stage_rules.h):
// how shader collections out there name their files, and the pipeline key that groups the stages of
// one pipeline (the name without its stage part).
#include "transpiler/source/stage_rules.h"

#include <gtest/gtest.h>

namespace stereoshift {
namespace {

std::optional<Stage> stageOf(const std::string& path) { return stageFromPath(path); }

TEST(StageRule, GlslcAndKhronosExtensions) {
  EXPECT_EQ(stageOf("shaders/a.vert"), Stage::Vertex);
  EXPECT_EQ(stageOf("shaders/a.tesc"), Stage::TessControl);
  EXPECT_EQ(stageOf("shaders/a.tese"), Stage::TessEvaluation);
  EXPECT_EQ(stageOf("shaders/a.geom"), Stage::Geometry);
  EXPECT_EQ(stageOf("shaders/a.frag"), Stage::Fragment);
  EXPECT_EQ(stageOf("shaders/a.comp"), Stage::Compute);
  EXPECT_EQ(stageOf("shaders/a.mesh"), Stage::Mesh);
}

TEST(StageRule, ShortExtensionsOfTutorials) {
  EXPECT_EQ(stageOf("5.1.parallax_mapping.vs"), Stage::Vertex);
  EXPECT_EQ(stageOf("5.1.parallax_mapping.fs"), Stage::Fragment);
  EXPECT_EQ(stageOf("explode.gs"), Stage::Geometry);
  EXPECT_EQ(stageOf("terrain.tcs"), Stage::TessControl);
  EXPECT_EQ(stageOf("terrain.tes"), Stage::TessEvaluation);
  EXPECT_EQ(stageOf("particles.cs"), Stage::Compute);
  EXPECT_EQ(stageOf("Shader.VS"), Stage::Vertex);  // case-insensitive
}

TEST(StageRule, ShaderAndHSuffixedExtensions) {
  EXPECT_EQ(stageOf("Basic.vsh"), Stage::Vertex);
  EXPECT_EQ(stageOf("Basic.fsh"), Stage::Fragment);
  EXPECT_EQ(stageOf("Basic.gsh"), Stage::Geometry);
  EXPECT_EQ(stageOf("SimpleTransform.vertexshader"), Stage::Vertex);
  EXPECT_EQ(stageOf("SingleColor.fragmentshader"), Stage::Fragment);
  EXPECT_EQ(stageOf("Explode.geometryshader"), Stage::Geometry);
  EXPECT_EQ(stageOf("Blur.computeshader"), Stage::Compute);
  EXPECT_EQ(stageOf("model.msh"), std::nullopt);  // a mesh file, not a mesh shader
}

TEST(StageRule, DoubleExtensions) {
  EXPECT_EQ(stageOf("shader.vert.glsl"), Stage::Vertex);
  EXPECT_EQ(stageOf("shader.frag.hlsl"), Stage::Fragment);
  EXPECT_EQ(stageOf("blur.comp.hlsl"), Stage::Compute);
  EXPECT_EQ(stageOf("a.vert.spv"), Stage::Vertex);
  EXPECT_EQ(stageOf("a.vs.fx"), Stage::Vertex);
}

TEST(StageRule, StageWordInHlslNames) {
  EXPECT_EQ(stageOf("basicVS.hlsl"), Stage::Vertex);
  EXPECT_EQ(stageOf("basicPS.hlsl"), Stage::Fragment);
  EXPECT_EQ(stageOf("water_vs.hlsl"), Stage::Vertex);
  EXPECT_EQ(stageOf("water_ps.hlsl"), Stage::Fragment);
  EXPECT_EQ(stageOf("VS_Skinned.hlsl"), Stage::Vertex);
  EXPECT_EQ(stageOf("PS-Skinned.hlsl"), Stage::Fragment);
  EXPECT_EQ(stageOf("TerrainHS.hlsl"), Stage::TessControl);
  EXPECT_EQ(stageOf("TerrainDS.hlsl"), Stage::TessEvaluation);
  EXPECT_EQ(stageOf("ExplodeGS.hlsl"), Stage::Geometry);
  EXPECT_EQ(stageOf("ReduceCS.hlsl"), Stage::Compute);
  EXPECT_EQ(stageOf("skybox_vertex.glsl"), Stage::Vertex);
  EXPECT_EQ(stageOf("SkyboxPixel.fx"), Stage::Fragment);
  // The last stage word decides: "Vertex" in VertexLitPS describes the lighting.
  EXPECT_EQ(stageOf("VertexLitPS.hlsl"), Stage::Fragment);
  // VSMain: the word ends where a lower-case letter starts the next one.
  EXPECT_EQ(stageOf("VSMain.hlsl"), Stage::Vertex);
}

TEST(StageRule, StageWordsOnlyAsWholeSeparatedParts) {
  EXPECT_EQ(stageOf("canvas.hlsl"), std::nullopt);    // "vs" inside a word
  EXPECT_EQ(stageOf("physics.hlsl"), std::nullopt);
  EXPECT_EQ(stageOf("pixelate.glsl"), std::nullopt);
  EXPECT_EQ(stageOf("skinned_mesh.hlsl"), std::nullopt);  // mesh, geometry, domain: not stage words in names
  EXPECT_EQ(stageOf("geometry_pass.glsl"), std::nullopt);
  EXPECT_EQ(stageOf("domain_warp.glsl"), std::nullopt);
  // Only beside a shader-language extension: tool files in a shader tree are not shaders.
  EXPECT_EQ(stageOf("notes_vs.txt"), std::nullopt);
  EXPECT_EQ(stageOf("build_cs.py"), std::nullopt);
}

TEST(StageRule, IncludeFilesHaveNoStage) {
  EXPECT_EQ(stageOf("common.glsl"), std::nullopt);
  EXPECT_EQ(stageOf("lighting.fxh"), std::nullopt);
  EXPECT_EQ(stageOf("CommonVS.hlsli"), std::nullopt);
  EXPECT_EQ(stageOf("noise.inc"), std::nullopt);
  EXPECT_TRUE(isIncludeOnlyName("shaders/Lighting.FXH"));
  EXPECT_FALSE(isIncludeOnlyName("shaders/effect.fx"));
}

TEST(StageRule, ExtraExtensions) {
  std::map<std::string, Stage> extra = {{"vp", Stage::Vertex}, {"fp", Stage::Fragment}};
  EXPECT_EQ(stageFromPath("Phong.vp", extra), Stage::Vertex);
  EXPECT_EQ(stageFromPath("Phong.FP", extra), Stage::Fragment);
  EXPECT_EQ(stageFromPath("Phong.vp"), std::nullopt);
  EXPECT_EQ(pipelineKey("dir/Phong.vp", extra), "dir/Phong");
}

TEST(StageRule, PipelineKeyDropsOnlyTheStagePart) {
  EXPECT_EQ(pipelineKey("lo/5.1.parallax_mapping.vs"), "lo/5.1.parallax_mapping");
  EXPECT_EQ(pipelineKey("lo/5.1.parallax_mapping.fs"), "lo/5.1.parallax_mapping");
  EXPECT_NE(pipelineKey("lo/5.1.parallax_mapping.vs"), pipelineKey("lo/5.2.steep_parallax.vs"));
  EXPECT_EQ(pipelineKey("shader.vert.glsl"), "shader");
  EXPECT_EQ(pipelineKey("shader.frag.glsl"), "shader");
  EXPECT_EQ(pipelineKey("shaders/terrain.vert.hlsl"), "shaders/terrain");
  EXPECT_EQ(pipelineKey("d3d/basicVS.hlsl"), "d3d/basic");
  EXPECT_EQ(pipelineKey("d3d/basicPS.hlsl"), "d3d/basic");
  EXPECT_EQ(pipelineKey("water_vs.hlsl"), "water");
  EXPECT_EQ(pipelineKey("water_ps.hlsl"), "water");
  EXPECT_EQ(pipelineKey("VS_water.hlsl"), "water");
  EXPECT_EQ(pipelineKey("Basic.vsh"), "Basic");
  EXPECT_EQ(pipelineKey("Basic.fsh"), "Basic");
  EXPECT_EQ(pipelineKey("SimpleTransform.vertexshader"), "SimpleTransform");
}

TEST(StageRule, PragmaShaderStage) {
  EXPECT_EQ(stageFromPragma("#version 450\n#pragma shader_stage(vertex)\nvoid main(){}").stage, Stage::Vertex);
  EXPECT_EQ(stageFromPragma("  #  pragma  shader_stage( fragment )\n").stage, Stage::Fragment);
  EXPECT_EQ(stageFromPragma("#pragma shader_stage(tesscontrol)").stage, Stage::TessControl);
  EXPECT_EQ(stageFromPragma("#pragma shader_stage(tesseval)").stage, Stage::TessEvaluation);
  EXPECT_EQ(stageFromPragma("#pragma optimize(on)\n").stage, std::nullopt);
  // The word split by a line splice (backslash-newline, also before CRLF) is still the pragma: the
  // shortcut that skips files never spelling `shader_stage` must not miss it.
  EXPECT_EQ(stageFromPragma("#pragma shader_\\\nstage(vertex)\n").stage, Stage::Vertex);
  EXPECT_EQ(stageFromPragma("#pragma sha\\\r\nder_stage(fragment)\r\n").stage, Stage::Fragment);
  EXPECT_EQ(stageFromPragma("#pragma \\\nshader_stage(compute)\n").stage, Stage::Compute);
  StageDecision bad = stageFromPragma("#version 450\n#pragma shader_stage(vortex)\n");
  EXPECT_EQ(bad.stage, std::nullopt);
  EXPECT_EQ(bad.problemLine, 2);
  EXPECT_EQ(bad.problemColumn, 22);
  EXPECT_NE(bad.problem.find("vortex"), std::string::npos);
}

// Read through the lexer: a pragma in a comment is none (the line scan took one in a block comment),
// and a comment inside the pragma is blank.
TEST(StageRule, PragmaShaderStageReadThroughTheLexer) {
  EXPECT_EQ(stageFromPragma("/*\n#pragma shader_stage(vertex)\n*/\n").stage, std::nullopt);
  EXPECT_EQ(stageFromPragma("// #pragma shader_stage(vertex)\n#pragma shader_stage(compute)\n").stage,
            Stage::Compute);
  EXPECT_EQ(stageFromPragma("#pragma shader_stage( /* stage */ fragment )\n").stage, Stage::Fragment);
  StageDecision open = stageFromPragma("#pragma shader_stage(\n");
  EXPECT_EQ(open.stage, std::nullopt);
  EXPECT_EQ(open.problemLine, 1);
  EXPECT_EQ(open.problemColumn, 22);
  EXPECT_NE(open.problem.find("unknown stage ''"), std::string::npos);
  StageDecision unclosed = stageFromPragma("#pragma shader_stage(vertex\n");
  EXPECT_EQ(unclosed.stage, std::nullopt);
  EXPECT_EQ(unclosed.problemColumn, 22);
}

TEST(StageRule, DecisionOrder) {
  // -S, then the pragma, then the name.
  EXPECT_EQ(decideStage("a.frag", "#pragma shader_stage(vertex)", Stage::Geometry).stage, Stage::Geometry);
  EXPECT_EQ(decideStage("a.frag", "#pragma shader_stage(vertex)", std::nullopt).stage, Stage::Vertex);
  StageDecision named = decideStage("a.frag", "void main(){}", std::nullopt);
  EXPECT_EQ(named.stage, Stage::Fragment);
  EXPECT_EQ(named.reason, "extension .frag");
  EXPECT_EQ(decideStage("<stdin>", "void main(){}", std::nullopt).stage, std::nullopt);
  EXPECT_NE(stageHint("common.glsl").find("-S"), std::string::npos);
  EXPECT_NE(stageHint("common.glsl").find("#pragma shader_stage"), std::string::npos);
}

TEST(TargetEnv, GlslcNames) {
  EXPECT_EQ(targetEnvFromName("vulkan1.2"), TargetEnv::Vulkan1_2);
  EXPECT_EQ(targetEnvFromName("opengl"), TargetEnv::OpenGL45);
  EXPECT_EQ(targetEnvFromName("opengl4.5"), TargetEnv::OpenGL45);
  EXPECT_EQ(targetEnvFromName("vulkan1.4"), std::nullopt);
  EXPECT_STREQ(targetEnvName(TargetEnv::Vulkan1_3), "vulkan1.3");
}

// 3Dmigoto's dumps: 16 hex digits, the stage's two letters, `_replace.txt`; each its own pipeline.
TEST(StageRule, ThreeDMigotoDumpNames) {
  EXPECT_EQ(stageOf3DMigotoDump("ShaderFixes/0123456789abcdef-vs_replace.txt"), Stage::Vertex);
  EXPECT_EQ(stageOf3DMigotoDump("0123456789ABCDEF-ps_replace.txt"), Stage::Fragment);
  EXPECT_EQ(stageOf3DMigotoDump("a/b/0123456789abcdef-ds_replace.txt"), Stage::TessEvaluation);
  EXPECT_EQ(stageOf3DMigotoDump("0123456789abcdef-cs_REPLACE.TXT"), Stage::Compute);
  // The assembly dumps 3Dmigoto writes beside the decompiled ones: `<hash>-vs.txt`.
  EXPECT_EQ(stageOf3DMigotoDump("ShaderCache/0123456789abcdef-vs.txt"), Stage::Vertex);
  EXPECT_EQ(stageOf3DMigotoDump("0123456789abcdef-gs.TXT"), Stage::Geometry);
  EXPECT_EQ(stageOfDecompiledDump("0123456789abcdef-vs_replace.txt"), Stage::Vertex);
  EXPECT_FALSE(stageOfDecompiledDump("0123456789abcdef-vs.txt"));
  for (const char* not_a_dump : {"0123456789abcdef-vs.text", "0123456789abcde-vs_replace.txt", "0123456789abcde-vs.txt",
                                 "0123456789abcdeg-vs_replace.txt", "0123456789abcdef-xs_replace.txt",
                                 "notes_vs_replace.txt", "0123456789abcdef-vs_replace.txt.bak"})
    EXPECT_FALSE(stageOf3DMigotoDump(not_a_dump)) << not_a_dump;
  StagedName named = readStagedName("ShaderFixes/0123456789abcdef-vs_replace.txt");
  EXPECT_EQ(named.stage, Stage::Vertex);
  EXPECT_EQ(named.key, "ShaderFixes/0123456789abcdef-vs_replace.txt");
  EXPECT_NE(pipelineKey("F/0123456789abcdef-vs_replace.txt"), pipelineKey("F/0123456789abcdef-ps_replace.txt"));
}

}  // namespace
}  // namespace stereoshift
