#include "ui/app/ui_driver.h"

#include <algorithm>
#include <chrono>

#include "core/common/error.h"
#include "storage/exchange/image_file.h"
#include "ui/app/ui_driver_scroll.h"

namespace rockface::ui {

namespace {

// Frames a scripted drag takes: enough that the slop is crossed on a frame
// of its own before the finger goes on.
constexpr int kDragFrames = 6;
// Start points drag_toward() tries across a panel.
constexpr int kStartPoints = 7;

}  // namespace

void UiDriver::settle() {
  // The outcome is taken inside a frame; a `then` may start another task.
  // The pairs' 3D images too: a script's "wait" waits for all the work.
  for (;;) {
    state().task.wait();
    state().reconstructions.wait();
    frame();
    if (!state().task.running() && !state().reconstructions.busy()) break;
  }
  frame();
}

void UiDriver::frames_until_input_consumed() {
  while (!input_.idle()) frame();
  frame();
}

void UiDriver::tap(float x, float y) {
  input_.push({TouchEvent::Kind::down, 0, x, y});
  input_.push({TouchEvent::Kind::up, 0, x, y});
  frames_until_input_consumed();
}

void UiDriver::tap(const std::string& label, const std::string& where) {
  auto target = state().targets.find(label);
  // A finger waits for the progress bar: what the worker's task disables
  // (Save while the blocks are updated) is tapped once it is done, so that a
  // script does not depend on how fast the machine runs the task.
  if (target && !target->enabled && state().task.running()) {
    settle();
    target = state().targets.find(label);
  }
  if (!target) throw InputError(where, "nothing labelled \"" + label + "\" on the screen");
  if (!target->enabled) throw InputError(where, "\"" + label + "\" is disabled on the screen");
  // A finger scrolls what is out of view into view first.
  if (!shown_whole(*target) && scrolled_out_of_view(*target)) {
    bring_into_view(label, where);
    target = state().targets.find(label);
  }
  // Cut by what no drag moves (the 3D image's edge): what shows is tapped.
  if (!target || !target->visible)
    throw InputError(where, "\"" + label + "\" is out of view on the screen");
  // The middle of the part in view: a finger taps what it sees.
  const ImVec2 c = target->shown_centre();
  tap(c.x, c.y);
}

int UiDriver::bring_into_view(const std::string& label, const std::string& where) {
  int drags = 0;
  // Each drag moves the content by at most the panel's height; a long list
  // takes a few. More than this and the drags are not moving it.
  constexpr int kMostDrags = 24;
  int stuck = 0;
  while (drags < kMostDrags) {
    const auto target = state().targets.find(label);
    if (!target) throw InputError(where, "nothing labelled \"" + label + "\" on the screen");
    // Whole in view, or cut only by what no drag moves.
    if (shown_whole(*target) || !scrolled_out_of_view(*target)) return drags;
    // Every start point tried without moving it: the drags do not reach it.
    const auto plan =
        stuck < kStartPoints ? drag_toward(*target, state().targets, stuck) : std::nullopt;
    if (!plan) throw InputError(where, "\"" + label + "\" cannot be scrolled into view by a drag");
    drag(plan->from, plan->to, kDragFrames);
    ++drags;
    const auto after = state().targets.find(label);
    // The same place after the drag: try the next start point.
    if (after && std::abs(after->min.x - target->min.x) < 0.5f &&
        std::abs(after->min.y - target->min.y) < 0.5f)
      ++stuck;
    else
      stuck = 0;
  }
  throw InputError(where, "\"" + label + "\" is still out of view after " +
                              std::to_string(kMostDrags) + " drags");
}

void UiDriver::drag(Eigen::Vector2f from, Eigen::Vector2f to, int frames) {
  input_.push({TouchEvent::Kind::down, 0, from.x(), from.y()});
  frames_until_input_consumed();
  for (int i = 1; i <= frames; ++i) {
    const Eigen::Vector2f p = from + (to - from) * (static_cast<float>(i) / frames);
    input_.push({TouchEvent::Kind::move, 0, p.x(), p.y()});
    frame();
  }
  input_.push({TouchEvent::Kind::up, 0, to.x(), to.y()});
  frames_until_input_consumed();
}

void UiDriver::pinch(Eigen::Vector2f centre, float from, float to, int frames) {
  auto fingers = [&](float spread, TouchEvent::Kind kind) {
    input_.push({kind, 0, centre.x() - spread / 2, centre.y()});
    input_.push({kind, 1, centre.x() + spread / 2, centre.y()});
  };
  fingers(from, TouchEvent::Kind::down);
  frames_until_input_consumed();
  for (int i = 1; i <= frames; ++i) {
    fingers(from + (to - from) * (static_cast<float>(i) / frames), TouchEvent::Kind::move);
    frames_until_input_consumed();
  }
  fingers(to, TouchEvent::Kind::up);
  frames_until_input_consumed();
}

void UiDriver::run(const ScriptStep& step, const std::filesystem::path& dir,
                   const std::string& where) {
  switch (step.kind) {
    case ScriptStep::Kind::tap:
      if (step.label.empty())
        tap(step.points[0].x(), step.points[0].y());
      else
        tap(step.label, where);
      break;
    case ScriptStep::Kind::drag:
      drag(step.points[0], step.points[1], step.frames);
      break;
    case ScriptStep::Kind::pinch:
      pinch(step.points[0], step.pinch_from, step.pinch_to, step.frames);
      break;
    case ScriptStep::Kind::wait_task:
      settle();
      break;
    case ScriptStep::Kind::frames:
      for (int i = 0; i < step.frames; ++i) frame();
      break;
    case ScriptStep::Kind::screenshot: {
      std::filesystem::create_directories(dir);
      const auto file = dir / (step.label + ".png");
      storage::write_image_file(file, screenshot());
      break;
    }
  }
}

ScriptRun run_ui_script(UiDriver& driver, const UiScript& script,
                        const std::filesystem::path& screenshots_dir) {
  ScriptRun out;
  driver.settle();  // the project given on the command line loads first
  for (std::size_t i = 0; i < script.steps.size(); ++i) {
    const ScriptStep& step = script.steps[i];
    // A step counts on the screen it starts on (a tab's tap on the screen
    // the finger left).
    const std::string screen = screen_name(driver.state().screen);
    auto use = std::find_if(out.screens.begin(), out.screens.end(),
                            [&](const ScreenUse& u) { return u.screen == screen; });
    if (use == out.screens.end()) use = out.screens.insert(out.screens.end(), {screen, 0, 0});
    const auto started = std::chrono::steady_clock::now();
    driver.run(step, screenshots_dir, "steps[" + std::to_string(i) + "]");
    use->seconds +=
        std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
    if (step.kind == ScriptStep::Kind::tap) ++use->taps;
    if (step.kind == ScriptStep::Kind::screenshot)
      out.screenshots.push_back(screenshots_dir / (step.label + ".png"));
  }
  driver.settle();
  out.status = driver.state().statuses.line(static_cast<std::size_t>(driver.state().screen));
  return out;
}

}  // namespace rockface::ui
