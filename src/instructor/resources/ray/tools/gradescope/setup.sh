#!/usr/bin/env bash
# Gradescope runs this once, when it builds the autograder's image. The grader needs a JDK (it
# compiles each submission) and nothing else: its libraries are in lib/, so grading never downloads.
# JDK 17 is the version the course builds with (--release 17).
set -euo pipefail
export DEBIAN_FRONTEND=noninteractive
apt-get update
apt-get install -y --no-install-recommends openjdk-17-jdk-headless
java -version
# Student code runs as this user, which cannot read the grader's files or write the results
# (ray.grading.Sandbox; setpriv comes with util-linux, in every Ubuntu image).
id -u ray1-student >/dev/null 2>&1 || useradd --system --no-create-home --shell /usr/sbin/nologin ray1-student
