#include "rl_common/registry.h"

#include <gtest/gtest.h>

#include <memory>
#include <string>

namespace {

struct Shape {
  virtual ~Shape() = default;
  virtual double area() const = 0;
};
struct Square : Shape {
  explicit Square(double s) : side(s) {}
  double area() const override { return side * side; }
  double side;
};
struct Circle : Shape {
  explicit Circle(double r) : radius(r) {}
  double area() const override { return 3.0 * radius * radius; }
  double radius;
};

using ShapeRegistry = rl_common::Registry<Shape, double>;

ShapeRegistry makeRegistry() {
  ShapeRegistry reg("shape");
  reg.add(
      "square", [](double s) { return std::make_unique<Square>(s); }, "four equal sides");
  reg.add("circle", [](double r) { return std::make_unique<Circle>(r); });
  reg.addAlias("round", "circle");
  return reg;
}

}  // namespace

TEST(Registry, CreatesByNameAndAlias) {
  const auto reg = makeRegistry();
  EXPECT_DOUBLE_EQ(reg.create("square", 2.0)->area(), 4.0);
  EXPECT_DOUBLE_EQ(reg.create("circle", 1.0)->area(), 3.0);
  EXPECT_DOUBLE_EQ(reg.create("round", 2.0)->area(), 12.0);
  EXPECT_EQ(reg.canonical("round"), "circle");
  EXPECT_EQ(reg.description("square"), "four equal sides");
}

TEST(Registry, UnknownNameListsValidNames) {
  const auto reg = makeRegistry();
  try {
    reg.create("triangle", 1.0);
    FAIL() << "expected an exception";
  } catch (const std::invalid_argument& e) {
    const std::string msg = e.what();
    EXPECT_NE(msg.find("unknown shape 'triangle'"), std::string::npos) << msg;
    EXPECT_NE(msg.find("circle, round, square"), std::string::npos) << msg;
  }
}

TEST(Registry, NamesAreSortedAndAliasesSeparate) {
  const auto reg = makeRegistry();
  EXPECT_EQ(reg.names(), (std::vector<std::string>{"circle", "square"}));
  EXPECT_EQ(reg.allNames(), (std::vector<std::string>{"circle", "round", "square"}));
  EXPECT_TRUE(reg.contains("round"));
  EXPECT_FALSE(reg.contains("triangle"));
}

TEST(Registry, DuplicatesAndBadAliasesAreRejected) {
  auto reg = makeRegistry();
  EXPECT_THROW(reg.add("square", [](double s) { return std::make_unique<Square>(s); }),
               std::invalid_argument);
  EXPECT_THROW(reg.addAlias("box", "cube"), std::invalid_argument);
  EXPECT_THROW(reg.addAlias("round", "square"), std::invalid_argument);
  EXPECT_THROW(reg.add("null", nullptr), std::invalid_argument);
}

TEST(Registry, EntriesCarryFactsAndTheOptionsTheyRead) {
  ShapeRegistry reg("shape");
  reg.add("square", [](double s) { return std::make_unique<Square>(s); }, "", {"polygon"},
          {"side"});
  reg.add("circle", [](double r) { return std::make_unique<Circle>(r); }, "", {},
          {"radius", "side"});
  reg.add("dot", [](double) { return std::make_unique<Circle>(0.0); });
  reg.addAlias("round", "circle");
  EXPECT_TRUE(reg.hasFact("square", "polygon"));
  EXPECT_FALSE(reg.hasFact("round", "polygon"));
  EXPECT_EQ(reg.namesWith("polygon"), std::vector<std::string>{"square"});
  EXPECT_TRUE(reg.takesOption("round", "radius"));
  EXPECT_FALSE(reg.takesOption("square", "radius"));
  EXPECT_FALSE(reg.takesOption("dot", "side"));
  EXPECT_EQ(reg.namesTaking("side"), (std::vector<std::string>{"circle", "square"}));
  EXPECT_TRUE(reg.namesTaking("colour").empty());
  EXPECT_EQ(reg.specificOptions(), (std::vector<std::string>{"radius", "side"}));
  EXPECT_THROW(reg.takesOption("hexagon", "side"), std::invalid_argument);
}

TEST(Registry, EntriesCarryOptionDefaultsAndNeeds) {
  ShapeRegistry reg = makeRegistry();
  EXPECT_TRUE(reg.defaults("square").empty());
  EXPECT_TRUE(reg.needs("square").empty());
  reg.setOptionValues("round", {{"colour", "red"}}, {{"radius", "1"}});
  const rl_common::OptionValues red{{"colour", "red"}};
  EXPECT_EQ(reg.defaults("circle"), red);  // set through the alias, read by the name
  EXPECT_EQ(reg.needs("round"), (rl_common::OptionValues{{"radius", "1"}}));
  EXPECT_TRUE(reg.defaults("square").empty());
  EXPECT_THROW(reg.setOptionValues("hexagon", {}), std::invalid_argument);
  EXPECT_THROW(reg.defaults("hexagon"), std::invalid_argument);
}
