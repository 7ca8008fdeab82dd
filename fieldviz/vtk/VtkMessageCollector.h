#pragma once
// VTK reports trouble through vtkOutputWindow (text on stderr) instead of exceptions. Observing an
// object's ErrorEvent and WarningEvent both silences that text and lets us keep the messages, so
// readers and writers can turn them into exceptions that name the file.
#include <string>
#include <vector>

#include <vtkSmartPointer.h>

class vtkAlgorithm;
class vtkCommand;
class vtkObject;
class vtkOutputWindow;

namespace fluidviz {

class VtkMessageCollector {
 public:
  VtkMessageCollector();

  /// Collects the errors and warnings `object` emits from now on.
  void watch(vtkObject* object);
  /// Watches the algorithm and its executive (which reports failed pipeline requests).
  void watchAlgorithm(vtkAlgorithm* algorithm);
  /// The observer itself, for VTK objects that take one (vtkXMLReader's parser observer).
  vtkCommand* command() const;

  bool hasErrors() const;
  const std::vector<std::string>& errors() const;
  const std::vector<std::string>& warnings() const;
  /// The errors, then the warnings, joined with "; " ("" when there were none). An executive's
  /// "returned failure for request" is left out when the algorithm said what went wrong.
  std::string summary() const;

 private:
  class Observer;
  vtkSmartPointer<Observer> observer_;
};

/// While alive, complaints of VTK objects that nobody observes go to `collector` instead of
/// stderr (VTK prints them through its logger and its output window). Needed where the object
/// cannot be observed: a reader's XML elements are created while it parses ("Unknown data type
/// "Bogus"" comes from one). Not thread-safe: both channels are global. Assumes no vtkLogger
/// callbacks are installed (the logger's stderr level is restored from its verbosity cutoff).
class VtkUnobservedMessagesCapture {
 public:
  explicit VtkUnobservedMessagesCapture(VtkMessageCollector& collector);
  ~VtkUnobservedMessagesCapture();
  VtkUnobservedMessagesCapture(const VtkUnobservedMessagesCapture&) = delete;
  VtkUnobservedMessagesCapture& operator=(const VtkUnobservedMessagesCapture&) = delete;

 private:
  class Window;
  vtkSmartPointer<Window> window_;
  vtkSmartPointer<vtkOutputWindow> previousWindow_;
  int previousStderrVerbosity_;
};

/// Words for a vtkErrorCode value ("out of disk space"); "" for NoError. Kept here because
/// vtkErrorCode's own string table lives in VTK::CommonMisc, which fluidviz_io does not link.
std::string describeVtkErrorCode(unsigned long code);

/// "vtkXMLImageDataReader (0x55d0): Error reading ..." -> "Error reading ..."; whitespace trimmed.
std::string conciseVtkMessage(const std::string& raw);

}  // namespace fluidviz
