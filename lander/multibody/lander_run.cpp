#include "lander/multibody/lander_run.h"

namespace touchdown::lander {

const char* LanderEventName(LanderEventKind kind) {
  switch (kind) {
    case LanderEventKind::kTouchdown: return "touchdown";
    case LanderEventKind::kCapture: return "capture";
    case LanderEventKind::kReleaseLiftoff: return "release_liftoff";
    case LanderEventKind::kReleaseSink: return "release_sink";
    case LanderEventKind::kReleaseSlide: return "release_slide";
    case LanderEventKind::kCrush: return "crush";
    case LanderEventKind::kLock: return "lock";
    case LanderEventKind::kBottom: return "bottom";
    case LanderEventKind::kStopReached: return "stop_reached";
    case LanderEventKind::kStopLeft: return "stop_left";
    case LanderEventKind::kTipOver: return "tip_over";
    case LanderEventKind::kRest: return "rest";
  }
  return "unknown";
}

}  // namespace touchdown::lander
