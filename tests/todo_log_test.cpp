// Each render keeps its own log of the unfinished stage code it ran: two renders side by side
// (the viewer's panes, or a pane and its reference) never see each other's TODOs, and a TODO
// that ran in an earlier render is not reported again by a later one that does not run it.
#include <gtest/gtest.h>

#include <thread>

#include "engine/recipe_builder.h"
#include "engine/render_session.h"
#include "scene/gltf_loader.h"
#include "stage_under_test.h"

namespace pathway {
namespace {

// Runs a TODO in every sample, or none: a stand-in for a skeleton and a finished stage.
class MaybeUnfinished : public Integrator {
 public:
  explicit MaybeUnfinished(bool unfinished) : unfinished_(unfinished) {}
  Color Li(const Ray&, SampleStream& samples, const RenderContext&) const override {
    if (unfinished_) PATHWAY_TODO("todo-log test: the unfinished integrator");
    return Color(samples.next1D());
  }

 private:
  bool unfinished_;
};

IntegratorInfo maybeUnfinished(const std::string& name, bool unfinished) {
  return {name,
          0,
          Variant::Reference,  // splatted by the reference's stage 1, which runs no TODO
          "todo-log test",
          {},
          SamplerType::Independent,
          [unfinished](const IntegratorSetup&) {
            return std::make_unique<MaybeUnfinished>(unfinished);
          }};
}
const bool kRegistered = registerIntegrator(maybeUnfinished("todo-test-unfinished", true)) &&
                         registerIntegrator(maybeUnfinished("todo-test-finished", false));

RenderRecipe recipeOf(const std::string& integrator) {
  return RecipeBuilder(integrator).size(48, 48).spp(64, 1);  // many passes: renders interleave
}

TEST(TodoLog, RendersSideBySideKeepTheirOwn) {
  PATHWAY_REQUIRE_REFERENCE();
  ASSERT_TRUE(kRegistered);
  const Scene scene = loadScene(std::string(PATHWAY_SCENES_DIR) + "/cornell_box.gltf");
  const RayTracer tracer(scene);
  for (int round = 0; round < 3; ++round) {
    RenderResult unfinished, finished;
    std::thread a([&] { unfinished = runRender(tracer, recipeOf("todo-test-unfinished")); });
    std::thread b([&] { finished = runRender(tracer, recipeOf("todo-test-finished")); });
    a.join();
    b.join();
    ASSERT_EQ(unfinished.todos.size(), 1u);
    EXPECT_EQ(unfinished.todos[0].file, "tests/todo_log_test.cpp");
    EXPECT_EQ(unfinished.metadata.todos, 1);
    EXPECT_TRUE(finished.todos.empty()) << finished.todos.front().task;
    EXPECT_EQ(finished.metadata.todos, 0);
  }
  // A later render that runs no TODO reports none, and one that runs it again reports it again.
  EXPECT_TRUE(runRender(tracer, recipeOf("todo-test-finished")).todos.empty());
  EXPECT_EQ(runRender(tracer, recipeOf("todo-test-unfinished")).todos.size(), 1u);
}

}  // namespace
}  // namespace pathway
