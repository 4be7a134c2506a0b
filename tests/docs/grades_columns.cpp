// Prints the header `aula grade` writes to grades.csv, for one world named <world> and one
// measure named <measure>, so the docs' column list is generated from the code that writes it
// (scripts/update-doc-lists.py).
#include <aula/grade/grades.hpp>

#include <iostream>

int main() {
  aula::grade::StudentGrade grade;
  grade.world_medians = {{"<world>", 0.0}};
  grade.measure_medians = {{"<measure>", 0.0}};
  const std::string csv = aula::grade::gradesCsv({grade});
  std::cout << csv.substr(0, csv.find('\n')) << "\n";
}
