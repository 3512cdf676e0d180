#include "stage_loading/student_stages.h"

#include <filesystem>

#include "core/error.h"
#include "render/integrator_registry.h"
#include "stage_loading/stage_library.h"
#include "stages/stage_catalog.h"

namespace pathway {

namespace fs = std::filesystem;

void loadStudentStages() {
  static bool loaded = false;
  if (loaded) return;
  loaded = true;
  for (int stage = 1; stage <= kStageCount; ++stage) {
    const StageInfo& declared = stageInfo(stage);
    // Linked in already (a test program): nothing to load.
    if (findStageIntegrator(stage, Variant::Student)) continue;
    const fs::path source = fs::path(PATHWAY_STUDENT_SOURCES_DIR) / declared.name / declared.file;
    const fs::path library = fs::path(PATHWAY_STUDENT_STAGES_DIR) / (declared.name + ".so");
    const std::string file = "assignments/" + declared.name + "/" + declared.file;
    std::error_code missing;
    if (!fs::exists(library, missing)) {
      noteMissingStage(stage, Variant::Student,
                       file + " has not been built" +
                           (fs::exists(source, missing)
                                ? " or did not compile (scripts/build shows the compiler's message)"
                                : std::string(" (the file is missing)")));
      continue;
    }
    // A library older than its file is from before the last edit: the build since then failed,
    // or has not run. Rendering it would show code the student no longer has.
    if (fs::exists(source, missing) &&
        fs::last_write_time(source, missing) > fs::last_write_time(library, missing)) {
      noteMissingStage(stage, Variant::Student,
                       file + " changed since it was last built (scripts/build builds it, " +
                           "or shows the compiler's message)");
      continue;
    }
    try {
      loadStageLibrary(library.string());
    } catch (const PathwayError& error) {
      noteMissingStage(stage, Variant::Student, file + ": " + error.what());
    }
  }
}

}  // namespace pathway
