"""The vacuum's `bounce` baseline (RandomBounce, components/vacuum/reference/RoombaReference.cpp)
line for line, with its random numbers drawn as libstdc++ draws them: std::mt19937_64 and
std::uniform_real_distribution<double> (generate_canonical: one 64-bit draw / 2^64)."""
import math

MASK_64 = (1 << 64) - 1


class Mt19937_64:
    """std::mt19937_64."""
    N, M = 312, 156
    UPPER, LOWER = 0xFFFFFFFF80000000, 0x7FFFFFFF

    def __init__(self, seed):
        self.state = [seed & MASK_64]
        for i in range(1, self.N):
            previous = self.state[-1]
            self.state.append((6364136223846793005 * (previous ^ (previous >> 62)) + i) & MASK_64)
        self.index = self.N

    def twist(self):
        s = self.state
        for i in range(self.N):
            y = (s[i] & self.UPPER) | (s[(i + 1) % self.N] & self.LOWER)
            s[i] = s[(i + self.M) % self.N] ^ (y >> 1) ^ (0xB5026F5AA96619E9 if y & 1 else 0)
        self.index = 0

    def next_u64(self):
        if self.index >= self.N:
            self.twist()
        y = self.state[self.index]
        self.index += 1
        y ^= (y >> 29) & 0x5555555555555555
        y ^= (y << 17) & 0x71D67FFFEDA60000
        y ^= (y << 37) & 0xFFF7EEE000000000
        return y ^ (y >> 43)

    def uniform(self, low, high):
        canonical = float(self.next_u64()) / 18446744073709551616.0
        if canonical >= 1.0:
            canonical = math.nextafter(1.0, 0.0)
        return canonical * (high - low) + low


def wrap_angle(a_rad):
    """aula::geometry::wrapAngle: [-pi, pi) by fmod, with its rounding."""
    r = math.fmod(a_rad + math.pi, 2 * math.pi)
    if r < 0:
        r += 2 * math.pi
    return r - math.pi


class Bounce:
    """Straight ahead at full speed until the bumper fires, back off, turn to a random heading."""
    FORWARD_MPS, BACKOFF_MPS, BACKOFF_S = 0.5, -0.15, 0.35
    TURN_MAX_RADPS, TURN_MIN_RADPS, TURN_GAIN_PER_S = 2.5, 0.4, 3.0
    TURN_TOLERANCE_RAD, TURN_TIMEOUT_S = 0.08, 4.0

    def __init__(self, seed):
        self.rng = Mt19937_64((seed * 2654435761 + 99) & MASK_64)
        self.t_s = 0.0
        self.phase = 0  # 0 forward, 1 back off, 2 turn
        self.phase_start_s = 0.0
        self.target_rad = 0.0

    def execute(self, period_s, yaw_rad, bumped):
        """One control period: (v m/s, w rad/s) from the yaw and the bumper."""
        self.t_s += period_s
        if bumped and self.phase == 0:
            self.phase, self.phase_start_s = 1, self.t_s
        v_mps, w_radps = self.FORWARD_MPS, 0.0
        if self.phase == 1:
            v_mps = self.BACKOFF_MPS
            if self.t_s - self.phase_start_s > self.BACKOFF_S:
                self.phase, self.phase_start_s = 2, self.t_s
                self.target_rad = wrap_angle(yaw_rad + self.rng.uniform(-math.pi, math.pi))
        elif self.phase == 2:
            v_mps = 0.0
            error_rad = wrap_angle(self.target_rad - yaw_rad)
            speed_radps = min(self.TURN_MAX_RADPS, self.TURN_MIN_RADPS + self.TURN_GAIN_PER_S * abs(error_rad))
            w_radps = math.copysign(speed_radps, error_rad)
            if abs(error_rad) < self.TURN_TOLERANCE_RAD or self.t_s - self.phase_start_s > self.TURN_TIMEOUT_S:
                self.phase = 0
        return v_mps, w_radps
