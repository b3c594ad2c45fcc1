#!/usr/bin/env bash
# Gradescope runs this once, when it builds the autograder's image. The grader needs a JDK (it
# compiles each submission) and nothing else: its libraries are in lib/, so grading never downloads.
# JDK 17 is the version the course builds with (--release 17).
set -euo pipefail
export DEBIAN_FRONTEND=noninteractive
apt-get update
apt-get install -y --no-install-recommends openjdk-17-jdk-headless
java -version
