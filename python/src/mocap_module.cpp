// The `mocap` Python module: the Qt-free core bound with pybind11 (README, "Python").

#include "bindings.h"

PYBIND11_MODULE(mocap, m)
{
  m.doc() = "Mocap Studio's core: read, clean, plan and solve facial motion capture takes.";
  mocap::python::bindErrors(m);
  mocap::python::bindTake(m);
  mocap::python::bindTakeFiles(m);
  mocap::python::bindCleaning(m);
  mocap::python::bindCleaningSteps(m);
  mocap::python::bindSolve(m);
  mocap::python::bindMarkerBinding(m);
  mocap::python::bindDeform(m);
  mocap::python::bindLayout(m);
  mocap::python::bindWriters(m);
  mocap::python::bindWeightCurves(m);
  mocap::python::bindReviewVideo(m);
}
