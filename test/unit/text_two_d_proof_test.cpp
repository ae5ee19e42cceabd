// The text route's 2D proof (transpiler/text_only_shift.h, textKeepsUnitW): which texts show every
// write of gl_Position with the literal w = 1, written the ways shaders out there write it, and which
// do not (a proof that says yes wrongly would leave a perspective draw mono in both eyes).
#include "transpiler/text_only_shift.h"

#include <gtest/gtest.h>

namespace stereoshift {
namespace {

std::string mainWith(const std::string& body) {
  return "#version 150\nin vec3 p;\nuniform mat4 m;\nvoid main()\n{\n" + body + "\n}\n";
}

TEST(TextTwoDProof, LiteralUnitWIsProof) {
  EXPECT_TRUE(textKeepsUnitW(mainWith("  gl_Position = vec4(p.xy, 0.0, 1.0);")));
  EXPECT_TRUE(textKeepsUnitW(mainWith("  gl_Position = vec4(p, 1);")));
  EXPECT_TRUE(textKeepsUnitW(mainWith("  gl_Position = vec4(p, 1.0f);")));
  EXPECT_TRUE(textKeepsUnitW(mainWith("  gl_Position = vec4(p, 1.);")));
  EXPECT_TRUE(textKeepsUnitW(mainWith("  gl_Position = vec4(1.0);")));
  // Comments between the tokens, the constructor's arguments calls of their own.
  EXPECT_TRUE(textKeepsUnitW(mainWith("  gl_Position /* NDC */ = vec4(max(p.x, 0.0), p.y, 0.0, // w\n 1.0);")));
  // Lanes without w, and w set to the literal one by itself.
  EXPECT_TRUE(textKeepsUnitW(mainWith("  gl_Position.xyz = p;\n  gl_Position.w = 1.0;")));
  EXPECT_TRUE(textKeepsUnitW(mainWith("  gl_Position = vec4(p, 1.0);\n  gl_Position.xy *= 0.5;")));
  // Reads of the position, and of the input position of a geometry shader.
  EXPECT_TRUE(textKeepsUnitW(mainWith("  gl_Position = vec4(p, 1.0);\n  vec4 c = gl_Position * 2.0;")));
  EXPECT_TRUE(textKeepsUnitW("#version 150\nlayout(points) in;\nlayout(points, max_vertices = 1) out;\n"
                             "void main() { vec4 q = gl_in[0].gl_Position; gl_Position = vec4(q.xy, 0.0, 1.0); "
                             "EmitVertex(); }\n"));
  // The built-in block redeclared, `invariant`.
  EXPECT_TRUE(textKeepsUnitW("#version 150\nout gl_PerVertex { vec4 gl_Position; };\ninvariant gl_Position;\n"
                             "void main() { gl_Position = vec4(0.0, 0.0, 0.0, 1.0); }\n"));
  // A text that writes no position breaks no other unit's proof.
  EXPECT_TRUE(textKeepsUnitW("#version 150\nvoid helper() { }\n"));
}

TEST(TextTwoDProof, AnyOtherWriteOfWIsNoProof) {
  EXPECT_FALSE(textKeepsUnitW(mainWith("  gl_Position = m * vec4(p, 1.0);")));
  EXPECT_FALSE(textKeepsUnitW(mainWith("  gl_Position = vec4(p, 1.0) * m;")));
  EXPECT_FALSE(textKeepsUnitW(mainWith("  gl_Position = vec4(p, 0.5);")));
  EXPECT_FALSE(textKeepsUnitW(mainWith("  gl_Position = vec4(p, -1.0);")));
  EXPECT_FALSE(textKeepsUnitW(mainWith("  gl_Position = vec4(p, 1.0 + p.z);")));
  EXPECT_FALSE(textKeepsUnitW(mainWith("  gl_Position = vec4(p, 1.0);\n  gl_Position.w = p.z;")));
  EXPECT_FALSE(textKeepsUnitW(mainWith("  gl_Position = vec4(p, 1.0);\n  gl_Position.zw = vec2(0.0, 1.0);")));
  EXPECT_FALSE(textKeepsUnitW(mainWith("  gl_Position = vec4(p, 1.0);\n  gl_Position *= 2.0;")));
  EXPECT_FALSE(textKeepsUnitW(mainWith("  gl_Position = vec4(p, 1.0);\n  gl_Position.w += 1.0;")));
  EXPECT_FALSE(textKeepsUnitW(mainWith("  gl_Position = vec4(p, 1.0);\n  gl_Position[3] = p.z;")));
  EXPECT_FALSE(textKeepsUnitW(mainWith("  gl_Position = p.z > 0.0 ? vec4(p, 1.0) : vec4(p, 1.0);")));
  // Handed to a function: an out parameter writes it.
  EXPECT_FALSE(textKeepsUnitW("#version 150\nin vec3 p;\nvoid place(out vec4 q) { q = vec4(p, p.z); }\n"
                              "void main() { place(gl_Position); }\n"));
  // Named in a macro: its uses cannot be read without expanding it.
  EXPECT_FALSE(textKeepsUnitW("#version 150\nin vec3 p;\n#define POS gl_Position\n"
                              "void main() { gl_Position = vec4(p, 1.0); POS = vec4(p, 2.0); }\n"));
  // A literal one in another base, or a w from a constant the text names: not read as the literal.
  EXPECT_FALSE(textKeepsUnitW(mainWith("  const float w = 1.0;\n  gl_Position = vec4(p, w);")));
}

// A unit alone proves nothing when it calls into a unit the pipeline does not hold: GLSL needs a
// prototype for such a function, and the unit has no body for it.
TEST(TextTwoDProof, PrototypesWithoutBodiesAreCallsIntoAnotherUnit) {
  EXPECT_TRUE(textDefinesEveryPrototype("#version 150\nvoid main() { }\n"));
  EXPECT_TRUE(textDefinesEveryPrototype("#version 150\nvec4 corner(int i);\nvoid main() { corner(0); }\n"
                                        "vec4 corner(int i) { return vec4(float(i)); }\n"));
  EXPECT_TRUE(textDefinesEveryPrototype("#version 150\nlayout(location = 0) in vec3 p;\nstruct S { vec4 v; };\n"
                                        "uniform Block { vec4 tint; } block;\nvoid main() { }\n"));
  EXPECT_FALSE(textDefinesEveryPrototype("#version 150\nvoid adjust();\nvoid main() { adjust(); }\n"));
  EXPECT_FALSE(textDefinesEveryPrototype("#version 150\nvec4 corner(int i);\n/* vec4 corner(int i) { } */\n"
                                         "void main() { corner(0); }\n"));
}

}  // namespace
}  // namespace stereoshift
