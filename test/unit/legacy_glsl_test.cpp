// Legacy GLSL (ESSL 100, desktop 110-150): the dialect decision for shaders without #version, the
// analysis translation to ESSL 310 / GLSL 330 (token by token, lines kept), and the source splice
// that puts the shift back into the original text, re-compiled at the original version.
#include "transpiler/backend/glsl_splice.h"
#include "transpiler/frontend/front_end.h"
#include "transpiler/frontend/legacy_glsl.h"
#include "transpiler/transpile_options.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

namespace stereoshift {
namespace {

LegacyDialect dialectOf(const std::string& text) { return decideLegacyDialect(text, findVersion(text)); }

LegacyTranslation translate(const std::string& text, Stage stage) {
  return translateLegacyGlsl(text, stage, dialectOf(text), "t.glsl");
}

long lines(const std::string& s) { return std::count(s.begin(), s.end(), '\n'); }

// The translation makes SPIR-V through the real front end.
bool frontEndAccepts(const std::string& text, Stage stage, Diagnostics& diags) {
  TranspileOptions options;
  options.stage = stage;
  options.language = SourceLanguage::Glsl;
  return compileToSpirv(SourceFile{"t.glsl", text}, options, diags).ok;
}

TEST(LegacyDialect, NoVersionIsDesktop110UnlessEsHints) {
  LegacyDialect plain = dialectOf("attribute vec3 a;\nvoid main() { gl_Position = vec4(a, 2.0); }\n");
  EXPECT_TRUE(plain.legacy);
  EXPECT_EQ(plain.version, 110);
  EXPECT_FALSE(plain.es);
  EXPECT_FALSE(plain.versionWritten);

  LegacyDialect precision = dialectOf("precision mediump float;\nvarying vec2 v;\nvoid main() {}\n");
  EXPECT_EQ(precision.version, 100);
  EXPECT_TRUE(precision.es);
  EXPECT_NE(precision.reason.find("precision"), std::string::npos);

  LegacyDialect guarded = dialectOf("#ifdef GL_ES\nprecision highp float;\n#endif\nvoid main() {}\n");
  EXPECT_TRUE(guarded.es);
  EXPECT_NE(guarded.reason.find("GL_ES"), std::string::npos);

  LegacyDialect extension = dialectOf("#extension GL_OES_standard_derivatives : enable\nvoid main() {}\n");
  EXPECT_TRUE(extension.es);

  // A precision word in a comment is no hint.
  EXPECT_FALSE(dialectOf("// precision mediump float;\nvoid main() {}\n").es);

  // Desktop-only built-ins win over everything.
  LegacyDialect compat = dialectOf("precision mediump float;\nvoid main() { gl_Position = ftransform(); }\n");
  EXPECT_EQ(compat.version, 110);
  EXPECT_FALSE(compat.es);
}

TEST(LegacyDialect, VersionedDialects) {
  EXPECT_TRUE(dialectOf("#version 100\nvoid main() {}\n").es);
  EXPECT_TRUE(dialectOf("#version 150\nvoid main() {}\n").legacy);
  EXPECT_FALSE(dialectOf("#version 330\nvoid main() {}\n").legacy);
  EXPECT_FALSE(dialectOf("#version 300 es\nvoid main() {}\n").legacy);
}

TEST(LegacyTranslation, Essl100VertexKeepsLines) {
  std::string src =
      "#version 100\n"
      "attribute vec3 aPos; // attribute in a comment stays\n"
      "varying vec2 vUv;\n"
      "uniform mat4 uMVP;\n"
      "void main() { vUv = aPos.xy; gl_Position = uMVP * vec4(aPos, 1.0); }\n";
  LegacyTranslation t = translate(src, Stage::Vertex);
  ASSERT_TRUE(t.ok) << t.error.message;
  EXPECT_EQ(t.text.find("#version 310 es\n"), 0u);
  EXPECT_NE(t.text.find("in vec3 aPos; // attribute in a comment stays"), std::string::npos);
  EXPECT_NE(t.text.find("out vec2 vUv;"), std::string::npos);
  EXPECT_EQ(t.text.find("varying"), std::string::npos);
  EXPECT_EQ(lines(t.text), lines(src));
  Diagnostics diags;
  EXPECT_TRUE(frontEndAccepts(src, Stage::Vertex, diags)) << diags.format();
}

TEST(LegacyTranslation, Essl100FragmentOutputsTexturesAndExtensions) {
  std::string src =
      "#version 100\n"
      "#extension GL_OES_standard_derivatives : enable\n"
      "#extension GL_EXT_shader_texture_lod : enable\n"
      "precision mediump float;\n"
      "varying vec2 vUv;\n"
      "uniform sampler2D uTex;\n"
      "uniform samplerCube uEnv;\n"
      "void main() {\n"
      "  vec4 c = texture2D(uTex, vUv) + textureCube(uEnv, vec3(vUv, 1.0)) + texture2DLodEXT(uTex, vUv, 2.0);\n"
      "  gl_FragColor = c * fwidth(vUv.x);\n"
      "  gl_FragDepthEXT = 0.5;\n"
      "}\n";
  LegacyTranslation t = translate(src, Stage::Fragment);
  ASSERT_TRUE(t.ok) << t.error.message;
  EXPECT_EQ(t.text.find("#extension"), std::string::npos);
  EXPECT_NE(t.text.find("precision mediump float;"), std::string::npos);  // default precision kept
  EXPECT_NE(t.text.find("in vec2 vUv;"), std::string::npos);
  EXPECT_NE(t.text.find("texture(uTex, vUv) + texture(uEnv"), std::string::npos);
  EXPECT_NE(t.text.find("textureLod(uTex, vUv, 2.0)"), std::string::npos);
  EXPECT_NE(t.text.find("out mediump vec4 stereoshift_FragColor;"), std::string::npos);
  EXPECT_NE(t.text.find("stereoshift_FragColor = c"), std::string::npos);
  EXPECT_NE(t.text.find("gl_FragDepth = 0.5"), std::string::npos);
  EXPECT_EQ(lines(t.text), lines(src));
  Diagnostics diags;
  EXPECT_TRUE(frontEndAccepts(src, Stage::Fragment, diags)) << diags.format();
}

TEST(LegacyTranslation, FragDataBecomesAnOutputArray) {
  std::string src =
      "precision mediump float;\n#extension GL_EXT_draw_buffers : require\nvoid main() {\n"
      "  gl_FragData[0] = vec4(1.0);\n  gl_FragData[1] = vec4(0.0);\n}\n";
  LegacyTranslation t = translate(src, Stage::Fragment);
  ASSERT_TRUE(t.ok) << t.error.message;
  EXPECT_NE(t.text.find("stereoshift_FragData[gl_MaxDrawBuffers]"), std::string::npos);
  Diagnostics diags;
  EXPECT_TRUE(frontEndAccepts(src, Stage::Fragment, diags)) << diags.format();
}

TEST(LegacyTranslation, DesktopCompatibilityBuiltins) {
  std::string src =
      "#version 120\n"
      "varying vec3 n;\n"
      "void main() {\n"
      "  n = gl_NormalMatrix * gl_Normal;\n"
      "  gl_TexCoord[0] = gl_TextureMatrix[0] * gl_MultiTexCoord0;\n"
      "  gl_FrontColor = gl_Color;\n"
      "  gl_Position = ftransform( );\n"
      "}\n";
  LegacyTranslation t = translate(src, Stage::Vertex);
  ASSERT_TRUE(t.ok) << t.error.message;
  EXPECT_EQ(t.text.find("#version 330\n"), 0u);
  EXPECT_NE(t.text.find("gl_Position = (stereoshift_ModelViewProjectionMatrix * stereoshift_Vertex);"),
            std::string::npos);
  EXPECT_NE(t.text.find("in vec4 stereoshift_Vertex;"), std::string::npos);
  EXPECT_NE(t.text.find("uniform mat4 stereoshift_TextureMatrix[8];"), std::string::npos);
  EXPECT_NE(t.text.find("out vec4 stereoshift_TexCoord[8];"), std::string::npos);
  EXPECT_NE(t.text.find("uniform mat3 stereoshift_NormalMatrix;"), std::string::npos);
  EXPECT_EQ(t.text.find("gl_MultiTexCoord0"), std::string::npos);
  EXPECT_EQ(lines(t.text), lines(src));
  Diagnostics diags;
  EXPECT_TRUE(frontEndAccepts(src, Stage::Vertex, diags)) << diags.format();
}

TEST(LegacyTranslation, FragmentColorIsTheInterpolatedFrontColor) {
  std::string src = "#version 110\nuniform sampler2D texture;\nvoid main() {\n"
                    "  gl_FragColor = gl_Color * texture2D(texture, gl_TexCoord[0].st);\n}\n";
  LegacyTranslation t = translate(src, Stage::Fragment);
  ASSERT_TRUE(t.ok) << t.error.message;
  EXPECT_NE(t.text.find("in vec4 stereoshift_FrontColor;"), std::string::npos);
  EXPECT_NE(t.text.find("in vec4 stereoshift_TexCoord[8];"), std::string::npos);
  // `texture` is a name in 110 and a built-in function in 330: the user's one is renamed.
  EXPECT_NE(t.text.find("texture(texture_stereoshift, "), std::string::npos);
  Diagnostics diags;
  EXPECT_TRUE(frontEndAccepts(src, Stage::Fragment, diags)) << diags.format();
}

TEST(LegacyTranslation, ShadowLookupsKeepTheirVec4) {
  std::string src = "#version 120\nuniform sampler2DShadow s;\nvarying vec4 c;\n"
                    "void main() { gl_FragColor = shadow2DProj(s, c) + shadow2D(s, c.xyz); }\n";
  LegacyTranslation t = translate(src, Stage::Fragment);
  ASSERT_TRUE(t.ok) << t.error.message;
  EXPECT_NE(t.text.find("vec4 stereoshift_shadow2DProj(sampler2DShadow s, vec4 c)"), std::string::npos);
  Diagnostics diags;
  EXPECT_TRUE(frontEndAccepts(src, Stage::Fragment, diags)) << diags.format();
}

TEST(LegacyTranslation, NoVersionGetsOneAndLineOne) {
  std::string src = "attribute vec4 p;\nvoid main() { gl_Position = p; }\n";
  LegacyTranslation t = translate(src, Stage::Vertex);
  ASSERT_TRUE(t.ok);
  EXPECT_EQ(t.text.find("#version 330\n#line 1\nin vec4 p;"), 0u);
  // glslang's errors point at the user's line: an error on line 2 of the source is reported there.
  Diagnostics diags;
  EXPECT_FALSE(frontEndAccepts("attribute vec4 p;\nvoid main() { gl_Position = q; }\n", Stage::Vertex, diags));
  ASSERT_TRUE(diags.hasErrors());
  EXPECT_EQ(diags.all().front().line, 2);
}

TEST(LegacyTranslation, DeclarationsGoOutsideConditionals) {
  std::string src = "#ifdef GL_ES\nprecision mediump float;\n#endif\nvarying vec2 v;\n"
                    "void main() { gl_FragColor = vec4(v, 0.0, 1.0); }\n";
  LegacyTranslation t = translate(src, Stage::Fragment);
  ASSERT_TRUE(t.ok);
  EXPECT_NE(t.text.find("#endif\nout mediump vec4 stereoshift_FragColor; in vec2 v;"), std::string::npos) << t.text;
}

// The fixed-function state is declared for the analysis as structs of stereoshift's own, once each.
TEST(LegacyTranslation, DeclaresFixedFunctionStateAsStructs) {
  std::string src = "#version 110\nvoid main() {\n  gl_FrontColor = gl_LightSource[0].diffuse + gl_LightSource[1].ambient;\n"
                    "  gl_Position = ftransform();\n}\n";
  LegacyTranslation t = translate(src, Stage::Vertex);
  ASSERT_TRUE(t.ok) << t.error.message;
  EXPECT_NE(t.text.find("struct stereoshift_LightSourceParameters { vec4 ambient; vec4 diffuse;"), std::string::npos)
      << t.text;
  EXPECT_NE(t.text.find("uniform stereoshift_LightSourceParameters stereoshift_LightSource[8];"), std::string::npos)
      << t.text;
  EXPECT_EQ(t.text.find("struct stereoshift_LightSourceParameters"),
            t.text.rfind("struct stereoshift_LightSourceParameters"));
  EXPECT_NE(t.text.find("stereoshift_LightSource[1].ambient"), std::string::npos) << t.text;
}

// What stays untranslatable is refused at its location: a geometry stage's compatibility inputs.
TEST(LegacyTranslation, RefusesUntranslatableStateWithItsLocation) {
  std::string src = "#version 150 compatibility\nlayout(points) in;\nlayout(points, max_vertices = 1) out;\n"
                    "void main() {\n  gl_FrontColor = gl_FrontColorIn[0];\n  EmitVertex();\n}\n";
  LegacyTranslation t = translate(src, Stage::Geometry);
  ASSERT_FALSE(t.ok);
  EXPECT_EQ(t.error.line, 5);
  EXPECT_EQ(t.error.column, 19);
  EXPECT_NE(t.error.message.find("gl_FrontColorIn"), std::string::npos);
}

TEST(LegacyTranslation, AttributeOutsideVertexIsAnError) {
  LegacyTranslation t = translate("#version 100\nattribute vec2 a;\nvoid main() {}\n", Stage::Fragment);
  ASSERT_FALSE(t.ok);
  EXPECT_EQ(t.error.line, 2);
  EXPECT_EQ(t.error.column, 1);
}

TEST(LegacyTranslation, Desktop130To150KeepTheirInOut) {
  for (const char* version : {"130", "140", "150"}) {
    std::string src = std::string("#version ") + version +
                      "\nin vec3 p;\nout vec3 v;\nuniform mat4 m;\nvoid main() { v = p; gl_Position = m * vec4(p, 1.0); }\n";
    LegacyTranslation t = translate(src, Stage::Vertex);
    ASSERT_TRUE(t.ok) << version;
    EXPECT_EQ(t.text, "#version 330" + src.substr(12)) << version;
    Diagnostics diags;
    EXPECT_TRUE(frontEndAccepts(src, Stage::Vertex, diags)) << version << diags.format();
  }
}

GlslSpliceOptions spliceOptions(int version, bool es) {
  GlslSpliceOptions o;
  o.version = version;
  o.es = es;
  return o;
}

TEST(GlslSplice, RenamesMainAndAppendsTheShift) {
  std::string src = "attribute vec3 aPos;\nuniform mat4 uMVP;\n"
                    "void main(void) { gl_Position = uMVP * vec4(aPos, 1.0); } // main\n";
  GlslSpliceResult r = spliceGlslStereo(src, spliceOptions(100, true));
  ASSERT_TRUE(r.ok) << r.error;
  // Everything before the appended block is the source with `main` renamed, comments untouched.
  EXPECT_EQ(r.text.find("attribute vec3 aPos;\nuniform mat4 uMVP;\nvoid main_stereoshift_mono(void) {"), 0u);
  EXPECT_NE(r.text.find("} // main\n"), std::string::npos);
  EXPECT_NE(r.text.find("uniform float eyeSign;\nuniform float separation;\nuniform float convergence;\n"),
            std::string::npos);
  EXPECT_NE(r.text.find("abs(gl_Position.w) <= 3.40282347e+38"), std::string::npos);  // no isinf in ESSL 100
  EXPECT_NE(r.text.find("gl_Position.x = gl_Position.x + (eyeSign * separation) * (gl_Position.w - convergence);"),
            std::string::npos);
  Diagnostics diags;
  EXPECT_TRUE(verifyLegacyCompiles(r.text, Stage::Vertex, 100, true, "out.vert", diags)) << diags.format() << r.text;
}

// Read through the lexer: a name written across a line splice is the name (the old scanners split
// it in two); a rename keeps the splice's line break, so no later line moves.
TEST(LegacyTranslation, SplicedNamesAreRenamedAndKeepTheirLines) {
  std::string src = "attribute vec2 uv;\nuniform sampler2D t;\nvoid main() { gl_Position = texture2\\\nD(t, uv); }\n";
  LegacyTranslation out = translate(src, Stage::Vertex);
  ASSERT_TRUE(out.ok) << out.error.message;
  EXPECT_NE(out.text.find("gl_Position = texture\\\n(t, uv);"), std::string::npos) << out.text;
  EXPECT_EQ(lines(out.text), lines(src) + 2);  // the #version and #line 1 put in front
}

TEST(GlslSplice, SplicedMainIsRenamedAndKeepsItsLines) {
  std::string src = "attribute vec3 p;\nvoid ma\\\nin() { gl_Position = vec4(p, 1.0); }\n";
  GlslSpliceResult r = spliceGlslStereo(src, spliceOptions(100, true));
  ASSERT_TRUE(r.ok) << r.error;
  EXPECT_EQ(r.text.find("attribute vec3 p;\nvoid main_stereoshift_mono\\\n() {"), 0u) << r.text;
  // Comments and string-free directives other than #define are not code: nothing renamed there.
  GlslSpliceResult commented = spliceGlslStereo("/* main */\n#ifdef main\n#endif\nvoid main() {}\n", spliceOptions(100, true));
  ASSERT_TRUE(commented.ok);
  EXPECT_EQ(commented.text.find("/* main */\n#ifdef main\n#endif\nvoid main_stereoshift_mono() {}"), 0u);
}

TEST(GlslSplice, CutoffFormsAndHaloCopies) {
  std::string src = "#version 130\nin vec4 p;\nout vec4 clip;\nvoid main() { gl_Position = p; clip = gl_Position; }\n";
  GlslSpliceOptions o = spliceOptions(130, false);
  o.form = ShiftForm::Select;
  o.cutoff = CutoffMode::Exact;
  o.haloCopies = exactPositionCopies(src);
  ASSERT_EQ(o.haloCopies, std::vector<std::string>{"clip"});
  GlslSpliceResult r = spliceGlslStereo(src, o);
  ASSERT_TRUE(r.ok);
  EXPECT_NE(r.text.find("gl_Position.x = (eyeSign != 0.0 && gl_Position.w != 1.0 && !isinf(gl_Position.w)) ? "),
            std::string::npos)
      << r.text;
  EXPECT_NE(r.text.find("    clip = gl_Position;\n}"), std::string::npos);
  o.cutoff = CutoffMode::None;
  EXPECT_NE(spliceGlslStereo(src, o).text.find("(eyeSign != 0.0) ?"), std::string::npos);
  Diagnostics diags;
  EXPECT_TRUE(verifyLegacyCompiles(r.text, Stage::Vertex, 130, false, "out.vert", diags)) << diags.format();
}

TEST(GlslSplice, DerivedOutputsAreNoExactCopies) {
  std::string src = "varying vec4 a, b;\nvoid main() { gl_Position = vec4(1.0); a = gl_Position; "
                    "b = gl_Position; b = gl_Position * 0.5; }\n";
  EXPECT_EQ(exactPositionCopies(src), std::vector<std::string>{"a"});
}

// A view ray's position: the right-hand side of its one assignment wrapped, a comment after the
// expression left outside the call, a declaration list ended by its comma; ESSL 100 compiles it.
// Refused where the text changes the position again (a compound operator, a member, a step) or
// assigns it twice.
TEST(GlslSplice, ViewRayAssignmentWrapped) {
  std::string src = "precision mediump float;\nuniform sampler2D d;\nuniform mat4 p;\nvarying vec3 r;\n"
                    "void main() { vec3 pos = r * texture2D(d, r.xy).x /* linear */, n = r; "
                    "gl_FragColor = vec4(pos + n, 1.0); }\n";
  GlslSpliceOptions o = spliceOptions(100, true);
  o.shift = false;
  o.viewRays.push_back({"pos", "vec3", "stereoshift_view_ray_pos", "(1.0 / p[0][0])"});
  GlslSpliceResult r = spliceGlslStereo(src, o);
  ASSERT_TRUE(r.ok) << r.error;
  EXPECT_NE(r.text.find("vec3 pos = stereoshift_view_ray_pos(r * texture2D(d, r.xy).x) /* linear */, n = r;"),
            std::string::npos)
      << r.text;
  EXPECT_NE(r.text.find("highp vec3 stereoshift_view_ray_pos(highp vec3 stereoshift_p)"), std::string::npos);
  Diagnostics diags;
  EXPECT_TRUE(verifyLegacyCompiles(r.text, Stage::Fragment, 100, true, "out.frag", diags)) << diags.format() << r.text;
  for (const std::string& change : {"pos *= 2.0;", "pos.x = 0.0;", "pos++;", "--pos;", "pos <<= 1;", "pos = r;"}) {
    std::string changed = src;
    changed.insert(changed.find("gl_FragColor"), change + " ");
    GlslSpliceResult refused = spliceGlslStereo(changed, o);
    EXPECT_FALSE(refused.ok) << change;
    EXPECT_NE(refused.error.find("'pos'"), std::string::npos) << refused.error;
  }
  // Read or compared, the position is not changed: `pos == r`, `pos <= r` are no assignments.
  std::string compared = src;
  compared.insert(compared.find("gl_FragColor"), "bool same = pos == r || pos.x <= r.x; ");
  EXPECT_TRUE(spliceGlslStereo(compared, o).ok);
}

TEST(GlslSplice, WithoutMainIsAnError) {
  EXPECT_FALSE(spliceGlslStereo("void notMain() {}\n", spliceOptions(110, false)).ok);
}

TEST(LegacyVerify, RejectsWhatTheDialectLacks) {
  Diagnostics diags;
  // `in` storage does not exist in ESSL 100.
  EXPECT_FALSE(verifyLegacyCompiles("#version 100\nin vec4 p;\nvoid main() { gl_Position = p; }\n", Stage::Vertex,
                                    100, true, "x.vert", diags));
  EXPECT_TRUE(diags.hasErrors());
  Diagnostics ok;
  EXPECT_TRUE(verifyLegacyCompiles("void main() { gl_Position = ftransform(); }\n", Stage::Vertex, 110, false,
                                   "y.vert", ok))
      << ok.format();
}

}  // namespace
}  // namespace stereoshift
