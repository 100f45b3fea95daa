#include "harness/generator.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <fstream>

#include "test_support.h"

namespace mfz {
namespace {

std::string plugin(const std::string& name) { return std::string(MANIFUZZ_PLUGIN_DIR) + "/lib" + name + ".so"; }

std::string open_error(const std::string& spec) {
  std::string error;
  EXPECT_FALSE(Generator::open(spec, error)) << spec << " should not load";
  EXPECT_EQ(error.find('\n'), std::string::npos) << "errors are one line";
  return error;
}

TEST(GeneratorLoading, BuiltinIsReachedByName) {
  std::string error;
  const auto g = Generator::open("builtin", error);
  ASSERT_TRUE(g) << error;
  EXPECT_EQ(g->name(), "manifuzz-clipping");
}

TEST(GeneratorLoading, TheClippingPluginAnswersBitForBitLikeTheBuiltin) {
  std::string error;
  const auto loaded = Generator::open(std::string(MANIFUZZ_PLUGIN_DIR) + "/libmanifuzz_clipping.so", error);
  ASSERT_TRUE(loaded) << error;
  const CaseFile c = test::make_case(test::box_points(2, 2, 0.5), {}, test::box_points(0.5, 0.5, 0.5),
                                     {Vec3(0.1, 0.2, 0.9), test::about(Vec3(1, 2, 3), 0.1)});
  const auto a = run_case(c, *loaded, error), b = run_case(c, Generator::builtin(), error);
  ASSERT_TRUE(a && b) << error;
  EXPECT_EQ(a->manifold.contact_count, b->manifold.contact_count);
  EXPECT_EQ(0, std::memcmp(&a->manifold, &b->manifold,
                           offsetof(mfz_manifold, contacts) + sizeof(mfz_contact) * b->manifold.contact_count));
}

TEST(GeneratorLoading, MissingFileIsAOneLineError) {
  EXPECT_NE(open_error("/nonexistent/libnothing.so").find("cannot load generator"), std::string::npos);
}

TEST(GeneratorLoading, TextFileIsNotAGenerator) {
  const std::string path = ::testing::TempDir() + "/not_a_library.so";
  std::ofstream(path) << "this is text\n";
  EXPECT_NE(open_error(path).find("cannot load generator"), std::string::npos);
}

TEST(GeneratorLoading, MissingSymbolIsNamed) {
  EXPECT_NE(open_error(plugin("mfz_test_missing_symbol")).find("does not export mfz_generate"), std::string::npos);
}

TEST(GeneratorLoading, WrongAbiVersionIsRefused) {
  EXPECT_NE(open_error(plugin("mfz_test_wrong_abi")).find("ABI version 2"), std::string::npos);
}

TEST(GeneratorLoading, UnknownNameIsRefused) {
  EXPECT_NE(open_error("nosuchgenerator").find("unknown generator"), std::string::npos);
}

TEST(GeneratorLoading, FieldsAGeneratorLeavesUnsetArePoisoned) {
  std::string error;
  const auto g = Generator::open(plugin("mfz_test_forgetful"), error);
  ASSERT_TRUE(g) << error;
  const CaseFile c = test::make_case(test::box_points(1, 1, 1), {}, test::box_points(1, 1, 1),
                                     {Vec3(0, 0, 1.9), Quat::Identity()});
  const auto run = run_case(c, *g, error);
  ASSERT_TRUE(run) << error;
  EXPECT_TRUE(std::isnan(run->manifold.normal.x));
  ASSERT_NE(run->verdict.first_violation(), nullptr);
  EXPECT_EQ(run->verdict.first_violation()->name, "finite");
}

}  // namespace
}  // namespace mfz
