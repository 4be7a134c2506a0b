// The vacuum's student API: what the exercise gives the student, and what it withholds.
#include <aula/vacuum/vacuum_algorithm.hpp>

#include <gtest/gtest.h>

#include <type_traits>

using namespace aula::vacuum;

namespace {

template <typename T, typename = void>
struct HasGetX : std::false_type {};
template <typename T>
struct HasGetX<T, std::void_t<decltype(std::declval<T&>().getX())>> : std::true_type {};
template <typename T, typename = void>
struct HasGetY : std::false_type {};
template <typename T>
struct HasGetY<T, std::void_t<decltype(std::declval<T&>().getY())>> : std::true_type {};

}  // namespace

TEST(VacuumApi, GivesTheStudentNoPosition) {
  // No localization in this exercise: the pose the student gets has a yaw and nothing else.
  static_assert(!HasGetX<YawSensor>::value, "YawSensor must not expose x");
  static_assert(!HasGetY<YawSensor>::value, "YawSensor must not expose y");
  static_assert(std::is_same_v<decltype(std::declval<VacuumApi&>().pose3d), YawSensor&>);
  SUCCEED();
}
