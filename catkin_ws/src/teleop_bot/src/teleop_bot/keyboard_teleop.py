"""The turtlebot_teleop keyboard layout, with time-based smoothing.

Keys move towards a target (speed * x, turn * th); the command approaches the target at a
fixed acceleration, and a held key (the terminal's auto-repeat) keeps it alive. When no
movement key arrives for `key_timeout` seconds, the target falls to zero: the robot stops
smoothly instead of running away.
"""

HELP = """
Control Your Turtlebot!
---------------------------
Moving around:
   u    i    o
   j    k    l
   m    ,    .

q/z : increase/decrease max speeds by 10%
w/x : increase/decrease only linear speed by 10%
e/c : increase/decrease only angular speed by 10%
space key, k : force stop
anything else : stop smoothly

CTRL-C to quit
"""

# key: (linear direction, angular direction); positive angular turns left (REP 103)
MOVE_BINDINGS = {
    "i": (1, 0),
    "o": (1, -1),
    "j": (0, 1),
    "l": (0, -1),
    "u": (1, 1),
    ",": (-1, 0),
    ".": (-1, 1),
    "m": (-1, -1),
}

# key: (linear factor, angular factor)
SPEED_BINDINGS = {
    "q": (1.1, 1.1),
    "z": (0.9, 0.9),
    "w": (1.1, 1.0),
    "x": (0.9, 1.0),
    "e": (1.0, 1.1),
    "c": (1.0, 0.9),
}

STOP_KEYS = (" ", "k")
QUIT_KEYS = ("\x03", "\x04")  # Ctrl-C, Ctrl-D when the terminal is in raw mode


def status_line(speed, turn):
    # %g prints the start values as the book shows them: "speed 0.2 turn 1"
    return "currently:\tspeed %.4g\tturn %.4g " % (speed, turn)


def approach(current, target, max_step):
    if target > current:
        return min(target, current + max_step)
    if target < current:
        return max(target, current - max_step)
    return target


class KeyboardTeleop:
    def __init__(
        self,
        speed=0.2,
        turn=1.0,
        linear_accel=0.2,
        angular_accel=1.0,
        key_timeout=0.75,
    ):
        self.speed = speed
        self.turn = turn
        self.linear_accel = linear_accel
        self.angular_accel = angular_accel
        self.key_timeout = key_timeout
        self.x = 0
        self.th = 0
        self.control_speed = 0.0
        self.control_turn = 0.0
        self.last_move_time = None
        self.speed_changes = 0
        self.quit = False

    def on_key(self, key, now):
        """Handle one character; returns text to print (or "")."""
        if key in MOVE_BINDINGS:
            self.x, self.th = MOVE_BINDINGS[key]
            self.last_move_time = now
            return ""
        if key in SPEED_BINDINGS:
            lin, ang = SPEED_BINDINGS[key]
            self.speed *= lin
            self.turn *= ang
            text = status_line(self.speed, self.turn)
            self.speed_changes += 1
            if self.speed_changes % 15 == 0:
                text += "\n" + HELP
            return text
        if key in STOP_KEYS:
            self.x = self.th = 0
            self.control_speed = self.control_turn = 0.0
            return ""
        if key in QUIT_KEYS:
            self.quit = True
            return ""
        # anything else: stop smoothly
        self.x = self.th = 0
        return ""

    def step(self, now, dt):
        """Advance the smoothing by dt seconds; returns (linear x, angular z)."""
        if self.last_move_time is not None and now - self.last_move_time > self.key_timeout:
            self.x = self.th = 0
            self.last_move_time = None
        dt = max(0.0, dt)
        self.control_speed = approach(
            self.control_speed, self.speed * self.x, self.linear_accel * dt
        )
        self.control_turn = approach(
            self.control_turn, self.turn * self.th, self.angular_accel * dt
        )
        return (self.control_speed, self.control_turn)
