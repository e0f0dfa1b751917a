!> The only bind(C) interface to METIS 5.1 (Karypis and Kumar, "A fast and high quality
!> multilevel scheme for partitioning irregular graphs", SIAM J. Sci. Comput. 20(1), 1998;
!> METIS 5.1.0 manual, 2013). idx_t and real_t are 32 bits wide in the installed metis.h
!> (IDXTYPEWIDTH = REALTYPEWIDTH = 32), so they map to c_int32_t and c_float.
!> metis_part_kway partitions a weighted graph in CSR form (0-based adjacency, as METIS
!> expects) with METIS_PartGraphKway after METIS_SetDefaultOptions, with a fixed seed so a
!> partition is reproducible run to run.
module dx_metis
   use, intrinsic :: iso_c_binding, only: c_int32_t, c_ptr, c_null_ptr
   use dx_error, only: error_t, set_error, EXIT_INPUT
   use dx_strings, only: str
   implicit none
   private
   public :: metis_part_kway, METIS_SEED, METIS_KWAY, METIS_RECURSIVE

   integer, parameter :: idx_t = c_int32_t
   integer, parameter :: METIS_NOPTIONS = 40
   ! option indices (0-based positions in options[], moptions_et in metis.h)
   integer, parameter :: METIS_OPTION_SEED = 8, METIS_OPTION_NUMBERING = 17
   integer, parameter :: METIS_OPTION_CONTIG = 11
   integer, parameter :: METIS_OK = 1, METIS_ERROR_INPUT = -2, METIS_ERROR_MEMORY = -3
   !> the fixed seed (any fixed value gives a reproducible partition)
   integer, parameter :: METIS_SEED = 20260
   !> methods: k-way (the default) and recursive bisection
   integer, parameter :: METIS_KWAY = 1, METIS_RECURSIVE = 2

   interface
      function c_metis_setdefaultoptions(options) bind(C, name='METIS_SetDefaultOptions') &
            result(rc)
         import :: idx_t
         integer(idx_t), intent(inout) :: options(*)
         integer(idx_t) :: rc
      end function c_metis_setdefaultoptions

      function c_metis_partgraphkway(nvtxs, ncon, xadj, adjncy, vwgt, vsize, adjwgt, &
            nparts, tpwgts, ubvec, options, edgecut, part) bind(C, name='METIS_PartGraphKway') &
            result(rc)
         import :: idx_t, c_ptr
         integer(idx_t), intent(in) :: nvtxs, ncon, nparts
         integer(idx_t), intent(in) :: xadj(*), adjncy(*), vwgt(*), adjwgt(*)
         type(c_ptr), value :: vsize, tpwgts, ubvec
         integer(idx_t), intent(in) :: options(*)
         integer(idx_t), intent(out) :: edgecut
         integer(idx_t), intent(out) :: part(*)
         integer(idx_t) :: rc
      end function c_metis_partgraphkway

      function c_metis_partgraphrecursive(nvtxs, ncon, xadj, adjncy, vwgt, vsize, adjwgt, &
            nparts, tpwgts, ubvec, options, edgecut, part) &
            bind(C, name='METIS_PartGraphRecursive') result(rc)
         import :: idx_t, c_ptr
         integer(idx_t), intent(in) :: nvtxs, ncon, nparts
         integer(idx_t), intent(in) :: xadj(*), adjncy(*), vwgt(*), adjwgt(*)
         type(c_ptr), value :: vsize, tpwgts, ubvec
         integer(idx_t), intent(in) :: options(*)
         integer(idx_t), intent(out) :: edgecut
         integer(idx_t), intent(out) :: part(*)
         integer(idx_t) :: rc
      end function c_metis_partgraphrecursive
   end interface

contains

   !> Partition the graph (xadj(nv+1), 0-based adjncy, vertex weights vwgt, edge weights
   !> adjwgt) into np parts; part(nv) in 0..np-1. np = 1 calls nothing. method: METIS_KWAY
   !> (default, METIS_PartGraphKway) or METIS_RECURSIVE (METIS_PartGraphRecursive).
   subroutine metis_part_kway(nv, xadj, adjncy, vwgt, adjwgt, np, part, edgecut, error, method)
      integer, intent(in) :: nv, np
      integer, intent(in), optional :: method
      integer, intent(in) :: xadj(:), adjncy(:), vwgt(:), adjwgt(:)
      integer, intent(out) :: part(:)
      integer, intent(out) :: edgecut
      type(error_t), allocatable, intent(out) :: error
      integer(idx_t) :: options(METIS_NOPTIONS), rc, nvtxs, ncon, nparts, cut
      integer(idx_t), allocatable :: p(:), adj(:), aw(:)
      edgecut = 0
      if (np <= 1 .or. nv <= 1) then
         part(1:nv) = 0
         return
      end if
      if (np > nv) then
         call set_error(error, 'METIS: cannot split '//str(nv)//' graph vertices into '// &
                        str(np)//' parts (more parts than vertices)', EXIT_INPUT)
         return
      end if
      rc = c_metis_setdefaultoptions(options)
      if (rc /= METIS_OK) then
         call set_error(error, 'METIS_SetDefaultOptions failed (code '//str(int(rc))//')', &
                        EXIT_INPUT)
         return
      end if
      options(METIS_OPTION_SEED + 1) = METIS_SEED
      options(METIS_OPTION_NUMBERING + 1) = 0
      nvtxs = nv; ncon = 1; nparts = np
      allocate(p(nv))
      ! METIS reads adjncy/adjwgt through xadj only; a graph without edges still needs a
      ! valid (one-element) array behind the pointer
      if (size(adjncy) > 0) then
         adj = int(adjncy, idx_t); aw = int(adjwgt, idx_t)
      else
         adj = [0_idx_t]; aw = [1_idx_t]
      end if
      if (present(method)) then
         if (method == METIS_RECURSIVE) then
            rc = c_metis_partgraphrecursive(nvtxs, ncon, int(xadj, idx_t), adj, &
                    int(vwgt, idx_t), c_null_ptr, aw, nparts, c_null_ptr, c_null_ptr, &
                    options, cut, p)
         else
            rc = c_metis_partgraphkway(nvtxs, ncon, int(xadj, idx_t), adj, int(vwgt, idx_t), &
                    c_null_ptr, aw, nparts, c_null_ptr, c_null_ptr, options, cut, p)
         end if
      else
         rc = c_metis_partgraphkway(nvtxs, ncon, int(xadj, idx_t), adj, int(vwgt, idx_t), &
                 c_null_ptr, aw, nparts, c_null_ptr, c_null_ptr, options, cut, p)
      end if
      if (rc /= METIS_OK) then
         if (rc == METIS_ERROR_MEMORY) then
            call set_error(error, 'METIS partitioning: out of memory', EXIT_INPUT)
         else if (rc == METIS_ERROR_INPUT) then
            call set_error(error, 'METIS partitioning: input error (code -2)', EXIT_INPUT)
         else
            call set_error(error, 'METIS partitioning failed (code '//str(int(rc))//')', &
                           EXIT_INPUT)
         end if
         return
      end if
      part(1:nv) = int(p)
      edgecut = int(cut)
   end subroutine metis_part_kway
end module dx_metis
