// The prototype scanner: which file-scope functions it finds, and the prototypes it writes for them.
#include "board/loader/sketch_prototypes.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace stepdance::sim {
namespace {

std::vector<std::string> prototypes_of(const std::string& text) {
  std::vector<std::string> out;
  for (const SketchFunction& function : scan_sketch_functions(text).functions) out.push_back(function.prototype);
  return out;
}

TEST(SketchPrototypes, PlainFunctionsInOrderWithTheirLines) {
  const SketchScan scan =
      scan_sketch_functions("int x = 3;\n\nvoid setup() {\n  go(1);\n}\n\nvoid go(int steps) { x += steps; }\n");
  ASSERT_EQ(scan.functions.size(), 2u);
  EXPECT_EQ(scan.functions[0].prototype, "void setup();");
  EXPECT_EQ(scan.functions[1].prototype, "void go(int steps);");
  EXPECT_EQ(scan.functions[1].name, "go");
  EXPECT_EQ(scan.functions[1].line, 7u);
  EXPECT_EQ(scan.insertion_line, 3u);
  EXPECT_EQ(scan.insertion_offset, std::string("int x = 3;\n\n").size());
}

TEST(SketchPrototypes, StaticInlineTemplatesAndQualifiedTypes) {
  EXPECT_EQ(prototypes_of("static inline float half(float v) { return v / 2; }\n"),
            std::vector<std::string>{"static inline float half(float v);"});
  EXPECT_EQ(prototypes_of("template <typename T, int N = 2>\nT scaled(T value) { return value * N; }\n"),
            std::vector<std::string>{"template < typename T, int N = 2 > T scaled(T value);"});
  EXPECT_EQ(prototypes_of("const std::array<int, 2>& table(unsigned long *p) noexcept { return t; }\n"),
            std::vector<std::string>{"const std::array < int, 2 > & table(unsigned long * p) noexcept;"});
  EXPECT_EQ(prototypes_of("auto twice(int v) -> int { return 2 * v; }\n"),
            std::vector<std::string>{"auto twice(int v) -> int;"});
}

TEST(SketchPrototypes, ReturnTypesAndAttributesAsSketchesWriteThem) {
  const std::string text =
      "char *name_of(int pin) { return nullptr; }\n"
      "const String& label() { return text; }\n"
      "unsigned long\nelapsed_since(unsigned long start)\n{\n  return millis() - start;\n}\n"
      "FASTRUN void on_frame(void) {}\n"
      "extern \"C\" int from_c(void) { return 1; }\n"
      "__attribute__((noinline)) volatile float64_t *level_ptr() { return &level; }\n";
  EXPECT_EQ(prototypes_of(text),
            (std::vector<std::string>{"char * name_of(int pin);", "const String & label();",
                                      "unsigned long elapsed_since(unsigned long start);",
                                      "FASTRUN void on_frame(void);", "extern \"C\" int from_c(void);",
                                      "__attribute__((noinline)) volatile float64_t * level_ptr();"}));
  EXPECT_EQ(scan_sketch_functions(text).functions[2].line, 4u);  // the name's line, not the type's
}

TEST(SketchPrototypes, DefaultArgumentsStayInThePrototypeAndAreMarkedInTheDefinition) {
  const std::string text = "void move(float mm, float speed = 10.0f, int axis = max(1, 2)) {}\n";
  const SketchScan scan = scan_sketch_functions(text);
  ASSERT_EQ(scan.functions.size(), 1u);
  EXPECT_EQ(scan.functions[0].prototype, "void move(float mm, float speed = 10.0f, int axis = max(1, 2));");
  ASSERT_EQ(scan.functions[0].default_arguments.size(), 2u);
  const auto [begin1, end1] = scan.functions[0].default_arguments[0];
  const auto [begin2, end2] = scan.functions[0].default_arguments[1];
  EXPECT_EQ(text.substr(begin1, end1 - begin1), "= 10.0f");
  EXPECT_EQ(text.substr(begin2, end2 - begin2), "= max(1, 2)");
}

TEST(SketchPrototypes, NotFunctionsAtFileScope) {
  const std::string text =
      "class Knob {\n public:\n  int read() { return 1; }\n};\n"
      "int Knob::twice() { return 2; }\n"
      "namespace helpers { void hidden() {} }\n"
      "extern \"C\" { void c_side() {} }\n"
      "struct Point { int x; } origin{};\n"
      "int table[] = {1, 2, 3};\n"
      "auto lambda = [](int v) { return v; };\n"
      "ISR(TIMER1_vect) { tick(); }\n"
      "bool operator==(const Knob&, const Knob&) { return true; }\n"
      "Encoder knob(ENCODER_1);\n"
      "void (*handler(int))(int) { return nullptr; }\n"
      "template <> int scaled<int>(int v) { return v; }\n";
  EXPECT_TRUE(scan_sketch_functions(text).functions.empty()) << prototypes_of(text).front();
}

TEST(SketchPrototypes, CommentsStringsAndCharactersHideBraces) {
  const std::string text =
      "// void commented() {}\n"
      "/* void block() { */\n"
      "const char* brace = \"{ void quoted() {\";\n"
      "char open = '{';\n"
      "const char* raw = R\"x(void raw() { )\" )x\";\n"
      "long big = 1'000'000;\n"
      "void real(const char* text = \"a, b\") { /* } */ }\n";
  const SketchScan scan = scan_sketch_functions(text);
  ASSERT_EQ(scan.functions.size(), 1u);
  EXPECT_EQ(scan.functions[0].prototype, "void real(const char * text = \"a, b\");");
  EXPECT_EQ(scan.functions[0].line, 7u);
}

TEST(SketchPrototypes, ConditionalsAreRecordedWithTheBranchesBeforeTheDefinition) {
  const std::string text =
      "#define module_driver\n"
      "#ifdef module_driver\n"
      "void driver_only() {}\n"
      "#elif defined(module_basic)\n"
      "void basic_only() {}\n"
      "#else\n"
      "#if \\\n  VERBOSE\n"
      "void verbose_other() {}\n"
      "#endif\n"
      "#endif\n"
      "void always() {}\n";
  const SketchScan scan = scan_sketch_functions(text);
  ASSERT_EQ(scan.functions.size(), 4u);
  using Lines = std::vector<std::vector<std::string>>;
  EXPECT_EQ(scan.functions[0].conditions, (Lines{{"#ifdef module_driver"}}));
  EXPECT_EQ(scan.functions[1].conditions, (Lines{{"#ifdef module_driver", "#elif defined(module_basic)"}}));
  EXPECT_EQ(scan.functions[2].conditions,
            (Lines{{"#ifdef module_driver", "#elif defined(module_basic)", "#else"}, {"#if    VERBOSE"}}));
  EXPECT_TRUE(scan.functions[3].conditions.empty());
  // Prototypes go before the conditional that holds the first definition, not inside it.
  EXPECT_EQ(scan.insertion_line, 2u);
}

TEST(SketchPrototypes, DirectivesInsideBodiesKeepTheConditionStackBalanced) {
  const std::string text =
      "void first() {\n#if A\n  one();\n#else\n  two();\n#endif\n}\n"
      "void second() {}\n";
  const SketchScan scan = scan_sketch_functions(text);
  ASSERT_EQ(scan.functions.size(), 2u);
  EXPECT_TRUE(scan.functions[1].conditions.empty());
}

TEST(SketchPrototypes, UnbalancedTextDoesNotCrash) {
  EXPECT_NO_FATAL_FAILURE(scan_sketch_functions("void f( {"));
  EXPECT_NO_FATAL_FAILURE(scan_sketch_functions("}}}} void g() {} \"unterminated\n#if X\n"));
  EXPECT_NO_FATAL_FAILURE(scan_sketch_functions("R\"x(never closed"));
  EXPECT_EQ(prototypes_of("}}}} void g() {}\n"), std::vector<std::string>{"void g();"});
}

TEST(SketchPrototypes, RandomTokenSoupNeverCrashesAndStaysInBounds) {
  static const char* const kPieces[] = {"void ", "int ", "f",   "g",   "(",  ")",       "{",         "}",
                                        ";",     ",",    "=",   "<",   ">",  "::",      "template ", "\"",
                                        "'",     "/*",   "*/",  "//",  "\n", "#if X\n", "#else\n",   "#endif\n",
                                        "\\\n",  "R\"(", ")\"", "1'0", " "};
  uint32_t state = 12345;  // a fixed linear congruential sequence: the same soup on every run
  for (int round = 0; round < 2000; ++round) {
    std::string text;
    for (int i = 0; i < 40; ++i) {
      state = state * 1664525u + 1013904223u;
      text += kPieces[(state >> 16) % (sizeof(kPieces) / sizeof(kPieces[0]))];
    }
    const SketchScan scan = scan_sketch_functions(text);
    ASSERT_LE(scan.insertion_offset, text.size()) << text;
    for (const SketchFunction& function : scan.functions) {
      for (const auto& [begin, end] : function.default_arguments) {
        ASSERT_LE(begin, end) << text;
        ASSERT_LE(end, text.size()) << text;
      }
      ASSERT_EQ(function.prototype.back(), ';') << text;
    }
  }
}

}  // namespace
}  // namespace stepdance::sim
