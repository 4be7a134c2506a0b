#include <aula/r/grade.hpp>
