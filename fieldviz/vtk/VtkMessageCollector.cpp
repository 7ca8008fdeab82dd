#include "fieldviz/vtk/VtkMessageCollector.h"

#include <cstring>

#include <vtkAlgorithm.h>
#include <vtkCommand.h>
#include <vtkErrorCode.h>
#include <vtkExecutive.h>
#include <vtkObject.h>
#include <vtkLogger.h>
#include <vtkObjectFactory.h>
#include <vtkOutputWindow.h>

namespace fluidviz {

class VtkMessageCollector::Observer : public vtkCommand {
 public:
  static Observer* New() { return new Observer; }
  vtkTypeMacro(Observer, vtkCommand);

  void Execute(vtkObject* caller, unsigned long event, void* callData) override {
    const std::string text = conciseVtkMessage(callData ? static_cast<const char*>(callData) : "");
    if (event == vtkCommand::WarningEvent)
      warnings.push_back(text);
    else if (vtkExecutive::SafeDownCast(caller))
      pipelineErrors.push_back(text);
    else
      errors.push_back(text);
  }

  std::vector<std::string> errors;
  // "Algorithm X returned failure for request: <dump>" only repeats that an error happened.
  std::vector<std::string> pipelineErrors;
  std::vector<std::string> warnings;
};

VtkMessageCollector::VtkMessageCollector() : observer_(vtkSmartPointer<Observer>::New()) {}

void VtkMessageCollector::watch(vtkObject* object) {
  if (!object) return;
  object->AddObserver(vtkCommand::ErrorEvent, observer_);
  object->AddObserver(vtkCommand::WarningEvent, observer_);
}

void VtkMessageCollector::watchAlgorithm(vtkAlgorithm* algorithm) {
  watch(algorithm);
  if (algorithm) watch(algorithm->GetExecutive());
}

vtkCommand* VtkMessageCollector::command() const { return observer_; }

bool VtkMessageCollector::hasErrors() const {
  return !observer_->errors.empty() || !observer_->pipelineErrors.empty();
}
const std::vector<std::string>& VtkMessageCollector::errors() const { return observer_->errors; }
const std::vector<std::string>& VtkMessageCollector::warnings() const {
  return observer_->warnings;
}

std::string VtkMessageCollector::summary() const {
  const auto& errors = observer_->errors.empty() ? observer_->pipelineErrors : observer_->errors;
  std::string joined;
  for (const std::string& m : errors) joined += (joined.empty() ? "" : "; ") + m;
  for (const std::string& m : observer_->warnings) joined += (joined.empty() ? "" : "; ") + m;
  return joined;
}

// Hands the output window's text to a collector's observer, as if the object had been watched.
class VtkUnobservedMessagesCapture::Window : public vtkOutputWindow {
 public:
  static Window* New() {
    auto* window = new Window;
    window->InitializeObjectBase();
    return window;
  }
  vtkTypeMacro(Window, vtkOutputWindow);

  void DisplayErrorText(const char* text) override { forward(vtkCommand::ErrorEvent, text); }
  void DisplayWarningText(const char* text) override { forward(vtkCommand::WarningEvent, text); }
  void DisplayGenericWarningText(const char* text) override {
    forward(vtkCommand::WarningEvent, text);
  }
  void DisplayText(const char* text) override { forward(vtkCommand::WarningEvent, text); }
  void DisplayDebugText(const char*) override {}

  vtkCommand* target = nullptr;

 private:
  void forward(unsigned long event, const char* text) {
    if (target) target->Execute(nullptr, event, const_cast<char*>(text ? text : ""));
  }
};

VtkUnobservedMessagesCapture::VtkUnobservedMessagesCapture(VtkMessageCollector& collector)
    : window_(vtkSmartPointer<Window>::New()),
      previousWindow_(vtkOutputWindow::GetInstance()),
      previousStderrVerbosity_(vtkLogger::GetCurrentVerbosityCutoff()) {
  window_->target = collector.command();
  vtkOutputWindow::SetInstance(window_);
  // vtkOutputWindowDisplayErrorText logs to stderr before it calls the output window.
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF);
}

VtkUnobservedMessagesCapture::~VtkUnobservedMessagesCapture() {
  vtkLogger::SetStderrVerbosity(static_cast<vtkLogger::Verbosity>(previousStderrVerbosity_));
  vtkOutputWindow::SetInstance(previousWindow_);
}

std::string describeVtkErrorCode(unsigned long code) {
  switch (code) {
    case vtkErrorCode::NoError: return "";
    case vtkErrorCode::FileNotFoundError: return "file not found";
    case vtkErrorCode::CannotOpenFileError: return "cannot open file";
    case vtkErrorCode::UnrecognizedFileTypeError: return "unrecognized file type";
    case vtkErrorCode::PrematureEndOfFileError: return "premature end of file";
    case vtkErrorCode::FileFormatError: return "file format error";
    case vtkErrorCode::NoFileNameError: return "no file name";
    case vtkErrorCode::OutOfDiskSpaceError: return "out of disk space";
    default:
      // Below VTK's own range the code is the system's errno (vtkErrorCode::GetLastSystemError).
      if (code < vtkErrorCode::FirstVTKErrorCode) return std::strerror(static_cast<int>(code));
      return "VTK error code " + std::to_string(code);
  }
}

std::string conciseVtkMessage(const std::string& raw) {
  // VTK sends observers "ERROR: In <source file>, line <n>\n<class> (<address>): <message>";
  // the source location and address mean nothing to users.
  std::string text = raw;
  if (text.rfind("ERROR: In ", 0) == 0 || text.rfind("Warning: In ", 0) == 0 ||
      text.rfind("Generic Warning: In ", 0) == 0) {
    const auto lineEnd = text.find('\n');
    text.erase(0, lineEnd == std::string::npos ? text.size() : lineEnd + 1);
  }
  const auto prefixEnd = text.find("): ");
  if (text.rfind("vtk", 0) == 0 && prefixEnd != std::string::npos) text.erase(0, prefixEnd + 3);
  const auto first = text.find_first_not_of(" \t\r\n");
  const auto last = text.find_last_not_of(" \t\r\n");
  if (first == std::string::npos) return {};
  text = text.substr(first, last - first + 1);
  for (char& c : text)
    if (c == '\n') c = ' ';
  return text;
}

}  // namespace fluidviz
