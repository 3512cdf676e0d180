// Which pixel each rendering thread is on, so that a grading child that crashes or runs past its
// time limit can say where: the renderer records the pixel before its samples, and the handlers
// installed by reportPixelsOnFatalSignals() print the pixels in progress to stderr before the
// signal ends the process as it would have.
#pragma once

#include <string>

namespace pathway {

// Called by the renderer once per pixel: one relaxed store to this thread's slot.
void recordPixelInProgress(int x, int y);
// The renderer is done with this thread's pixel (the pass ended).
void clearPixelInProgress();

// SIGSEGV, SIGILL, SIGFPE, SIGBUS, SIGABRT and SIGALRM print
//   pathway: stopped by SIGNAL while rendering pixel (x, y)[, (x, y) ...]
// then take their default action (the process ends by that signal).
void reportPixelsOnFatalSignals();

// The pixels named by such a line in `output` ("(12, 40)"), or "" when there is none.
std::string pixelsInProgressFrom(const std::string& output);

}  // namespace pathway
