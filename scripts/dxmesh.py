"""Structured hexahedron meshes for the deck generators: node ids of an (nx+1) x (ny+1) x
(nz+1) grid numbered x fastest from 1, the *NODE and *ELEMENT_SOLID cards of a box of
nx x ny x nz hex8, and a *SET_NODE_LIST of 8 ids per card. Used by gen_box_deck.py,
gen_cube_deck.py, gen_large_input_decks.py and thin_sweep.py."""


def grid_id(nx, ny):
    """node id of grid point (i, j, k), ids from 1, x fastest"""
    return lambda i, j, k: 1 + i + (nx + 1) * (j + (ny + 1) * k)


def box_cards(nx, ny, nz, hx, hy, hz, part=lambda e: 1, xfmt='%16.6f'):
    """the *NODE and *ELEMENT_SOLID lines (each ending in a newline) of the box
    [0, nx hx] x [0, ny hy] x [0, nz hz]; part(e) the part id of element e"""
    nid = grid_id(nx, ny)
    node = '%8d' + 3 * xfmt + '\n'
    yield '*NODE\n'
    for k in range(nz + 1):
        for j in range(ny + 1):
            for i in range(nx + 1):
                yield node % (nid(i, j, k), i * hx, j * hy, k * hz)
    yield '*ELEMENT_SOLID\n'
    e = 0
    for k in range(nz):
        for j in range(ny):
            for i in range(nx):
                e += 1
                yield '%8d%8d' % (e, part(e)) + ''.join('%8d' % m for m in (
                    nid(i, j, k), nid(i + 1, j, k), nid(i + 1, j + 1, k), nid(i, j + 1, k),
                    nid(i, j, k + 1), nid(i + 1, j, k + 1), nid(i + 1, j + 1, k + 1),
                    nid(i, j + 1, k + 1))) + '\n'


def node_list_cards(sid, ids):
    """*SET_NODE_LIST sid with the ids, 8 per card"""
    yield '*SET_NODE_LIST\n%10d\n' % sid
    for a in range(0, len(ids), 8):
        yield ''.join('%10d' % m for m in ids[a:a + 8]) + '\n'


def bottom_ids(nx, ny):
    """ids of the grid's face z = 0"""
    nid = grid_id(nx, ny)
    return [nid(i, j, 0) for j in range(ny + 1) for i in range(nx + 1)]
