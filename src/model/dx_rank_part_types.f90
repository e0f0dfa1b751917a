!> What one MPI rank holds of the serial model: the content of its rank file (written and
!> read by io/dx_rank_file, made by engine/dx_partition). A type of its own below both, so
!> io does not import the engine (architecture.md: a type the layers share lives in a
!> module that uses only base).
module dx_rank_part_types
   use dx_kinds, only: wp
   implicit none
   private
   public :: rank_part_t

   !> What one rank holds (the content of its rank file). Global indices are the dense
   !> 1-based indices of the serial model, ascending.
   type :: rank_part_t
      integer :: rank = 0, np = 1, ne_global = 0, nn_global = 0
      integer, allocatable :: elements(:)    !< global element indices, ascending
      integer, allocatable :: nodes(:)       !< global node indices, ascending
      integer, allocatable :: node_owner(:)  !< (size(nodes)) owning rank of each node
      integer, allocatable :: nbr(:)         !< neighbour ranks, ascending
      integer, allocatable :: nbr_ptr(:)     !< (size(nbr)+1) offsets into nbr_nodes
      integer, allocatable :: nbr_nodes(:)   !< nodes shared with each neighbour, ascending
      integer, allocatable :: spcs(:)        !< indices into model%spcs on local nodes
      integer, allocatable :: prescribed(:)  !< indices into model%prescribed
      integer, allocatable :: node_loads(:)  !< indices into model%node_loads
      integer, allocatable :: seg_loads(:)   !< indices into model%seg_loads computed here
      integer, allocatable :: wall_ptr(:)    !< (nwalls+1) offsets into wall_nodes
      integer, allocatable :: wall_nodes(:)  !< local slave nodes of each rigid wall
      integer, allocatable :: hist_nodes(:)  !< indices into model%db%hist_nodes
      !> The rank's sub-model (rank file format 2, group /model; dx_rank_submodel): the
      !> initial coordinates, velocities and labels of its nodes (order of nodes), and its
      !> pieces of the serial element blocks in serial block order: pieces(:, p) = serial
      !> block, dense part, element type; piece p's elements are piece_ptr(p) ..
      !> piece_ptr(p+1)-1 of piece_elem (global element), piece_pos (position in the serial
      !> block, ascending) and piece_conn (MAX_NEN, *): global nodes, 0 past the family's nen.
      real(wp), allocatable :: x0(:, :), v0(:, :)
      integer, allocatable :: node_label(:)
      integer, allocatable :: pieces(:, :), piece_ptr(:)
      integer, allocatable :: piece_elem(:), piece_pos(:), piece_conn(:, :)
      !> The records of spcs, prescribed and node_loads above, global node indices:
      !> spc_rec (7, *) node, DOF flags 1..6 (0/1); pm_int (4, *) node, dof, vad, curve and
      !> pm_real (6, *) sf, dir(3), death, birth; nl_int (3, *) node, dof, curve, nl_sf (*)
      integer, allocatable :: spc_rec(:, :), pm_int(:, :), nl_int(:, :)
      real(wp), allocatable :: pm_real(:, :), nl_sf(:)
   end type rank_part_t
end module dx_rank_part_types
