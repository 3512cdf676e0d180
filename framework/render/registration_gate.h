// Who may register a stage, and when. Stage files register themselves (render/stage_api.h)
// through functions the program exports to the stage libraries it loads, and those functions take
// the variant as an argument: left open, a student's library could register (or hand on
// functions) as the reference, or as another stage, or install something at render time. The gate
// admits a registration only
//   - while the program starts, for the stages linked into it (until endBuiltInRegistrations),
//   - or inside the window the loader opens around one library's load (stage_loading/
//     stage_library.h): its variant, and one stage.
// A refusal inside a window makes that library's load fail, naming what it tried (and nothing it
// registers after it is admitted); a registration outside any window (student code calling at
// render time) ends the process with a message.
#pragma once

#include <string>

#include "core/variant.h"

namespace pathway {

// A reference stage's library carries the code of the earlier stages (stage 3's wavefront version
// is stage 2's wave): in its window their registrations are skipped, not refused.
struct RegistrationWindow {
  Variant variant = Variant::Student;
  int stage = 0;  // the one stage it may register; 0: any one (its first registration fixes it)
};

// Opens the window for one library's load; closeRegistrationWindow returns what was refused in
// it ("" when nothing was) and restores what held before.
void openRegistrationWindow(const RegistrationWindow& window);
std::string closeRegistrationWindow();

// Ends the start-up registrations: the programs call it first thing in main(), after the stages
// linked into them registered. (The test program does not: its tests register as they go.)
void endBuiltInRegistrations();

// Whether a registration of stage `stage` (0: an integrator of no stage) in `variant` goes ahead.
// `what` names it for a refusal ("stage 1's functions", "stage3@ref").
bool admitRegistration(int stage, Variant variant, const std::string& what);

}  // namespace pathway
