#pragma once
// A test's hold on the office server at a named point (issue 46's pool
// test: a visit opening made observably slow where it must hold no
// database connection). Only when ROCKFACE_OFFICE_TEST_GATE names a
// folder: the server writes POINT.reached there, then waits until the test
// writes POINT.go (at most two minutes, so that a test that failed never
// leaves a server hanging). Without the variable it costs one getenv.
namespace rockface::app::office_web {

void test_gate(const char* point);

}  // namespace rockface::app::office_web
