#pragma once
// OpenTURNS set up once for sweetspot: its thread pool on one thread, so that its sums run in
// one order and a result is the same bits on any machine load (the study's points are what run
// in parallel), and its log quiet.
namespace sweetspot {
void configure_openturns();
}
