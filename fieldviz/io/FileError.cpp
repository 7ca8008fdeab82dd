#include "fieldviz/io/FileError.h"

namespace fluidviz {

FileError::FileError(std::filesystem::path path, const std::string& message,
                     std::string arrayName)
    : std::runtime_error(message), path_(std::move(path)), arrayName_(std::move(arrayName)) {}

}  // namespace fluidviz
