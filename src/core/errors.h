#pragma once
/// Typed exceptions of the froth engine. The Lua bindings turn each of them into a Lua error
/// with the same message; messages start with the operation ("cluster: ...", "step: ...").

#include <stdexcept>
#include <string>

namespace froth {

/// Base class of all froth errors.
struct Error : std::runtime_error {
    using std::runtime_error::runtime_error;
};
/// An argument or option is out of range or malformed (tau <= 0, unknown flow, sigma <= 0).
struct InvalidInput : Error {
    using Error::Error;
};
/// The combinatorics of a cluster are not supported (edge in 4 surfaces, open body, ...).
struct TopologyError : Error {
    using Error::Error;
};
/// The geometry is degenerate (zero-area facet, assumption (A) of the seed violated, NaN).
struct GeometryError : Error {
    using Error::Error;
};
/// A linear solve failed (singular or non-finite system).
struct SolverError : Error {
    using Error::Error;
};
/// An iteration did not converge (the nonlinear iteration of an r > 1 anisotropy).
struct ConvergenceError : SolverError {
    using SolverError::SolverError;
};
/// An error-controlled step missed its tolerance (flows/stepper.h set_error_tolerance); the
/// cluster is unchanged and the caller retries with a shorter step.
struct StepRejected : Error {
    StepRejected(const std::string& what, double error_estimate)
        : Error(what), estimate(error_estimate) {}
    double estimate; ///< the step's error estimate (StepCost::error_estimate)
};
/// The user asked to stop (Ctrl-C) an operation that cannot stop half-way and be kept
/// (meshing); nothing was built or changed.
struct Interrupted : Error {
    using Error::Error;
};
/// A file could not be read or written.
struct IoError : Error {
    using Error::Error;
};

} // namespace froth
