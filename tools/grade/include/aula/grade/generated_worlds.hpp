#pragma once
// Held-out worlds a teacher does not draw: `aula grade ... --worlds=generate:house:5,seed=7`
// writes 5 houses with the project's generators (share/aula/worlds/tools), deterministically
// from the seed, into OUT/worlds (each with its map, OUT/worlds/<name>.png), and grades on them.
// What varies is what matters to the exercise:
// - house (vacuum): the rooms (2-4 x 1-3), their sizes and doors, the furniture (1-3 boxes a
//   room), the start room and heading;
// - street (autopark): the slot (1.3 to 2 lengths of the 4 m car), the curb's offset, the neighbours' sizes
//   (car, van, small), the car's start;
// - city (teletaxi): the blocks (2-4 a side, split into buildings), the roads' width, the city's
//   size, and two destinations it declares (road crossings), over which it is graded.

#include <string>
#include <vector>

namespace aula::grade {

struct WorldsToGenerate {
  std::string kind;              // house | city | street: the exercise's declared generator
  std::string script;            // its generator in worlds/tools/ ("make_house.py")
  double map_resolution_m = 0.1; // the map drawn of each world, to check it
  int count = 0;
  long long seed = 1;
};

// "house for vacuum, city for teletaxi, ...": every declared exercise's generated worlds.
std::string generatedWorldKinds();
// Does this --worlds item start a generation ("generate:...")?
bool isGenerateItem(const std::string& item);
// "generate:house:5" with its "seed=7" item (or "" for seed 1). Throws config::ConfigError
// naming the item and what is wrong, or a kind that is not `exercise`'s.
WorldsToGenerate parseGenerate(const std::string& item, const std::string& seed_item, const std::string& exercise);

// Writes the worlds and their maps into `out_dir`/worlds (again: the same bytes) and returns the
// worlds' paths. `python` runs the generators, `mapgen` is aula-mapgen. Throws
// std::runtime_error naming the generator's complaint.
std::vector<std::string> generateWorlds(const WorldsToGenerate& what, const std::string& out_dir, const std::string& python,
                                        const std::string& mapgen);

// The generator's arguments for world `index` (1-based) of `what`: a pure function of the two.
std::vector<std::string> generatorArguments(const WorldsToGenerate& what, int index);

}  // namespace aula::grade
