"""A scene's script: its actions applied to a cloth at their frames, and its settings changed
on a running cloth. The CLI's run, the page's panels and its session all go through these."""

from cloth.scene import settings_scene
from cloth.hands import grab, move, move_by, release, pin, unpin, carry
from cloth.step import retune, cut
from cloth.obstacles import move_obstacle


def apply_settings(cloth, keys, where):
    scene = settings_scene(cloth.scene.settings, keys, where)
    # The grid's own keys and the script stay the cloth's: a set changes settings only.
    scene.pins = cloth.scene.pins
    scene.actions = cloth.scene.actions
    scene.frames = cloth.scene.frames
    scene.obstacles = cloth.scene.obstacles
    retune(cloth, scene)


def apply_action(cloth, action):
    op = action.op
    k = action.vertex
    if op == 'grab':
        if action.has_to:
            grab(cloth, k, action.to_x, action.to_y)
        else:
            grab(cloth, k, cloth.pos[k + k], cloth.pos[k + k + 1])
    elif op == 'move':
        if action.by:
            move_by(cloth, k, action.to_x, action.to_y)
        else:
            move(cloth, k, action.to_x, action.to_y)
    elif op == 'release':
        release(cloth, k)
    elif op == 'pin':
        pin(cloth, k)
    elif op == 'unpin':
        unpin(cloth, k)
    elif op == 'set':
        apply_settings(cloth, action.keys, 'scene')
    elif op == 'cut':
        cut(cloth, action.from_x, action.from_y, action.to_x, action.to_y)
    elif op == 'obstacle':
        move_obstacle(cloth, action.vertex, action.to_x, action.to_y)
    elif op == 'carry':
        carry(cloth, k, action.to_x, action.to_y)


def apply_due(cloth, next_action, f):
    """Apply the scene's actions from index `next_action` on whose frame is <= f (they come
    sorted by frame); return the index of the first one not yet due. The CLI and the page step
    scripted scenes through this one function."""
    actions = cloth.scene.actions
    while next_action < len(actions) and actions[next_action].frame <= f:
        apply_action(cloth, actions[next_action])
        next_action += 1
    return next_action


def drop_actions_after(cloth, f):
    """Forget the scene's actions after frame f (the page cuts a replayed recording so when a
    person takes over at frame f)."""
    actions = cloth.scene.actions
    keep = 0
    while keep < len(actions) and actions[keep].frame <= f:
        keep += 1
    cloth.scene.actions = actions[:keep]
