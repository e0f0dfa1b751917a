!> MPI tests of dx_par, run by scripts/run_mpi_tests.sh serially (no mpirun) and under
!> `mpirun --oversubscribe -np 2/3/4`. Rank 0 prints the checks; a check passes only when
!> it holds on every rank.
!>   mpi_par_test          reductions; fixed-order shared-node sums against the serial sum
!>   mpi_par_test abort    the last rank calls par_abort (the runner checks exit and message)
program mpi_par_test
   use, intrinsic :: iso_fortran_env, only: int64, output_unit
   use dx_kinds, only: wp
   use dx_error, only: error_t
   use dx_par, only: par_init, par_finalize, par_rank, par_size, par_allreduce, par_abort, &
                     par_barrier, PAR_SUM, PAR_MIN, PAR_MAX, par_minloc, par_minloc_flags
   use dx_par_plan, only: shared_sum_t, par_shared_setup, par_shared_sum, par_gather_ordered
   use dx_model, only: model_t
   use dx_partition, only: partition_t, rank_part_t, partition_elements, rank_part
   use dx_assert, only: check, assert_summary
   implicit none
   type(error_t), allocatable :: error
   integer :: np, me
   character(16) :: mode

   call par_init(error)
   if (allocated(error)) error stop 2
   np = par_size()
   me = par_rank()
   mode = ''
   if (command_argument_count() > 0) call get_command_argument(1, mode)
   if (mode == 'abort') then
      if (me == np - 1) call par_abort('deliberate abort by the test', 3)
      call par_barrier()
      call par_finalize()
      stop
   end if
   if (me == 0) write(output_unit, '(a,i0,a)') 'mpi_par_test on ', np, ' rank(s)'
   call test_reductions()
   call test_random_partition(1000, 400, 1)
   call test_random_partition(3000, 500, 2)
   call test_metis_box()
   call test_minloc()
   call test_minloc_flags()
   call test_ordered_energy()
   call par_finalize()
   if (me == 0) call assert_summary()

contains

   !> A check that must hold on every rank; rank 0 reports it.
   subroutine check_all(ok, name)
      logical, intent(in) :: ok
      character(*), intent(in) :: name
      integer :: bad
      bad = merge(0, 1, ok)
      call par_allreduce(bad, PAR_MAX)
      if (me == 0) call check(bad == 0, name)
   end subroutine check_all

   subroutine test_reductions()
      real(wp) :: r, ra(2)
      integer :: i, ia(2)
      r = real(me + 1, wp)
      call par_allreduce(r, PAR_SUM)
      call check_all(r == real(np*(np + 1)/2, wp), 'allreduce real sum = np(np+1)/2')
      i = me
      call par_allreduce(i, PAR_MIN)
      call check_all(i == 0, 'allreduce integer min of rank = 0')
      i = me
      call par_allreduce(i, PAR_MAX)
      call check_all(i == np - 1, 'allreduce integer max of rank = np-1')
      ra = [real(me, wp), -real(me, wp)]
      call par_allreduce(ra, PAR_MAX)
      call check_all(ra(1) == real(np - 1, wp) .and. ra(2) == 0.0_wp, 'allreduce real(:) max')
      ra = [real(me, wp), -real(me, wp)]
      call par_allreduce(ra, PAR_MIN)
      call check_all(ra(1) == 0.0_wp .and. ra(2) == -real(np - 1, wp), 'allreduce real(:) min')
      ia = [1, me]
      call par_allreduce(ia, PAR_SUM)
      call check_all(ia(1) == np .and. ia(2) == np*(np - 1)/2, 'allreduce integer(:) sum')
   end subroutine test_reductions

   !> Global minimum with the lowest key among ties (the serial loop's first minimum).
   subroutine test_minloc()
      real(wp) :: x
      integer :: key, lastev
      x = 1.0_wp + real(mod(me, 2), wp)
      key = 100 - 7*me
      call par_minloc(x, key)
      lastev = 2*((np - 1)/2)
      call check_all(x == 1.0_wp .and. key == 100 - 7*lastev, &
                     'par_minloc: minimum 1 held by the even ranks, lowest key among them')
   end subroutine test_minloc

   !> The stop/dump requests folded into the dt reduction (dx_checkpoint): the minimum and
   !> its key as par_minloc, and each flag the largest over the ranks - a request of one
   !> rank (the last: SIGTERM = 15; rank 1 or 0: SIGUSR1) reaches every rank; no request
   !> anywhere gives 0 on every rank.
   subroutine test_minloc_flags()
      real(wp) :: x
      integer :: key, lastev, flags(3)
      x = 1.0_wp + real(mod(me, 2), wp)
      key = 100 - 7*me
      flags = 0
      if (me == np - 1) flags(1) = 15
      if (me == min(1, np - 1)) flags(2) = 1
      call par_minloc_flags(x, key, flags)
      lastev = 2*((np - 1)/2)
      call check_all(x == 1.0_wp .and. key == 100 - 7*lastev, &
                     'par_minloc_flags: minimum and lowest key as par_minloc')
      call check_all(all(flags == [15, 1, 0]), &
                     'par_minloc_flags: flags of one rank reach all (largest over the ranks)')
      flags = 0
      x = real(me + 3, wp); key = me
      call par_minloc_flags(x, key, flags)
      call check_all(all(flags == 0) .and. x == 3.0_wp .and. key == 0, &
                     'par_minloc_flags: no request anywhere gives 0 flags')
   end subroutine test_minloc_flags

   !> Energies: 1000 per-element values (2 components, adversarial) in blocks of 128; the
   !> serial glstat sum is `e = e + sum(blk%eint)` block by block. Elements spread over the
   !> ranks (e*7 mod np); par_gather_ordered brings them back in key order and the same
   !> block-structured sum gives the serial bits on every rank.
   subroutine test_ordered_energy()
      integer, parameter :: NE = 1000, NB = 128
      real(wp) :: val(2, NE), ser(2), par(2)
      integer, allocatable :: mykeys(:), allk(:)
      real(wp), allocatable :: myvals(:, :), allv(:, :)
      integer(int64) :: st
      integer :: e, b
      st = 4711_int64
      do e = 1, NE
         val(1, e) = adversarial(st)
         val(2, e) = adversarial(st)
      end do
      ser = 0.0_wp
      do b = 1, NE, NB
         ser(1) = ser(1) + sum(val(1, b:min(b + NB - 1, NE)))
         ser(2) = ser(2) + sum(val(2, b:min(b + NB - 1, NE)))
      end do
      mykeys = pack([(e, e = 1, NE)], [(mod(7*e, np) == me, e = 1, NE)])
      myvals = val(:, mykeys)
      call par_gather_ordered(mykeys, myvals, allk, allv)
      par = 0.0_wp
      do b = 1, NE, NB
         par(1) = par(1) + sum(allv(1, b:min(b + NB - 1, NE)))
         par(2) = par(2) + sum(allv(2, b:min(b + NB - 1, NE)))
      end do
      call check_all(size(allk) == NE .and. all(allk == [(e, e = 1, NE)]), &
                     'par_gather_ordered: all 1000 keys, in order, on every rank')
      call check_all(all(transfer(par, 1_int64, 2) == transfer(ser, 1_int64, 2)), &
                     'ordered energy sum = serial block-by-block sum bit for bit')
   end subroutine test_ordered_energy

   !> A deterministic generator (Park and Miller minimal standard, 1988), in (0, 1).
   real(wp) function rnd(state)
      integer(int64), intent(inout) :: state
      state = modulo(16807_int64*state, 2147483647_int64)
      rnd = real(state, wp)/2147483647.0_wp
   end function rnd

   !> A value with an adversarial magnitude: random sign, mantissa and a power of ten in
   !> -30..30, so the rounding of a sum depends on its order.
   real(wp) function adversarial(state)
      integer(int64), intent(inout) :: state
      real(wp) :: s, m
      integer :: p
      s = merge(1.0_wp, -1.0_wp, rnd(state) < 0.5_wp)
      m = 1.0_wp + rnd(state)
      p = int(61.0_wp*rnd(state)) - 30
      adversarial = s*m*10.0_wp**p
   end function adversarial

   logical function bit_equal(a, b)
      real(wp), intent(in) :: a(:, :), b(:, :)
      bit_equal = all(transfer(a, 1_int64, size(a)) == transfer(b, 1_int64, size(b)))
   end function bit_equal

   !> ne elements with nen = 4 random distinct nodes out of nn, random values; elements are
   !> numbered in global order (key = element index). scheme 1: element e on a random
   !> rank; scheme 2: contiguous slabs of elements with random strays.
   subroutine test_random_partition(ne, nn, scheme)
      integer, intent(in) :: ne, nn, scheme
      integer, parameter :: NEN = 4, NC = 3
      integer :: conn(NEN, ne), epart(ne), e, k, j, n
      real(wp) :: val(NC, NEN, ne), ref(NC, nn)
      integer(int64) :: st
      integer, allocatable :: holders(:, :)
      st = 12345_int64 + scheme
      do e = 1, ne
         do k = 1, NEN
            do
               n = 1 + int(real(nn, wp)*rnd(st))
               if (.not. any(conn(1:k - 1, e) == n)) exit
            end do
            conn(k, e) = n
            do j = 1, NC
               val(j, k, e) = adversarial(st)
            end do
         end do
         if (scheme == 1) then
            epart(e) = int(real(np, wp)*rnd(st))
         else
            epart(e) = ((e - 1)*np)/ne
            if (rnd(st) < 0.1_wp) epart(e) = int(real(np, wp)*rnd(st))
         end if
      end do
      ! the serial sum: from 0, elements in global order
      ref = 0.0_wp
      do e = 1, ne
         do k = 1, NEN
            ref(:, conn(k, e)) = ref(:, conn(k, e)) + val(:, k, e)
         end do
      end do
      allocate(holders(0:np - 1, nn))
      holders = 0
      do e = 1, ne
         holders(epart(e), conn(:, e)) = 1
      end do
      call run_shared_sum(ne, nn, conn, epart, val, ref, holders, &
         'random data, '//trim(merge('random ranks  ', 'slabs + strays', scheme == 1)))
   end subroutine test_random_partition

   !> The shared-node sum on this rank against the serial sum ref, bit for bit, and the
   !> plain sum of per-rank partial sums (which must differ somewhere on this data).
   subroutine run_shared_sum(ne, nn, conn, epart, val, ref, holders, label)
      integer, intent(in) :: ne, nn, conn(:, :), epart(:), holders(0:, :)
      real(wp), intent(in) :: val(:, :, :), ref(:, :)
      character(*), intent(in) :: label
      integer :: e, k, n, q, nsh, nc, ndiff, ncomp
      integer, allocatable :: snum(:), nbr(:), nbr_ptr(:), nbr_snode(:), c_node(:), c_key(:)
      real(wp), allocatable :: loc(:, :), cval(:, :), res(:, :), part_sum(:, :)
      logical :: ok
      type(shared_sum_t) :: plan
      ncomp = size(val, 1)
      ! local shared numbering: nodes this rank holds together with another rank
      allocate(snum(nn))
      snum = 0
      nsh = 0
      do n = 1, nn
         if (holders(me, n) == 1 .and. sum(holders(:, n)) > 1) then
            nsh = nsh + 1
            snum(n) = nsh
         end if
      end do
      nbr = [integer ::]
      nbr_snode = [integer ::]
      allocate(nbr_ptr(1))
      nbr_ptr(1) = 1
      do q = 0, np - 1
         if (q == me) cycle
         k = 0
         do n = 1, nn
            if (snum(n) > 0 .and. holders(q, n) == 1) then
               nbr_snode = [nbr_snode, snum(n)]
               k = k + 1
            end if
         end do
         if (k > 0) then
            nbr = [nbr, q]
            nbr_ptr = [nbr_ptr, nbr_ptr(size(nbr_ptr)) + k]
         end if
      end do
      ! own elements in global order: interior nodes summed directly, shared ones recorded
      allocate(loc(ncomp, nn), cval(ncomp, size(conn, 1)*ne), c_node(size(conn, 1)*ne), &
               c_key(size(conn, 1)*ne), part_sum(ncomp, nn))
      loc = 0.0_wp
      part_sum = 0.0_wp
      nc = 0
      do e = 1, ne
         if (epart(e) /= me) cycle
         do k = 1, size(conn, 1)
            n = conn(k, e)
            part_sum(:, n) = part_sum(:, n) + val(:, k, e)
            if (snum(n) == 0) then
               loc(:, n) = loc(:, n) + val(:, k, e)
            else
               nc = nc + 1
               cval(:, nc) = val(:, k, e)
               c_node(nc) = snum(n)
               c_key(nc) = e
            end if
         end do
      end do
      call par_shared_setup(plan, nsh, nbr, nbr_ptr, nbr_snode, c_node(1:nc), c_key(1:nc))
      allocate(res(ncomp, nsh))
      call par_shared_sum(plan, cval(:, 1:nc), res)
      do n = 1, nn
         if (snum(n) > 0) loc(:, n) = res(:, snum(n))
      end do
      ok = .true.
      do n = 1, nn
         if (holders(me, n) == 1) ok = ok .and. bit_equal(loc(:, n:n), ref(:, n:n))
      end do
      call check_all(ok, 'shared-node sum = serial sum bit for bit ('//label//')')
      ! the same numbers summed as per-rank partials then over ranks: not the serial sum
      call par_allreduce(part_sum(:, 1), PAR_SUM)   ! keeps ranks in step (value unused)
      ndiff = 0
      do n = 1, nn
         if (sum(holders(:, n)) < 2) cycle
         if (me == 0) then
            block
               real(wp) :: tot(ncomp)
               integer :: r, ee, kk
               ! partial sums per rank in rank order, as a plain reduction would add them
               tot = 0.0_wp
               do r = 0, np - 1
                  block
                     real(wp) :: p(ncomp)
                     p = 0.0_wp
                     do ee = 1, ne
                        if (epart(ee) /= r) cycle
                        do kk = 1, size(conn, 1)
                           if (conn(kk, ee) == n) p = p + val(:, kk, ee)
                        end do
                     end do
                     tot = tot + p
                  end block
               end do
               if (.not. bit_equal(reshape(tot, [ncomp, 1]), ref(:, n:n))) ndiff = ndiff + 1
            end block
         end if
      end do
      call par_allreduce(ndiff, PAR_MAX)
      if (np > 1) then
         call check_all(ndiff > 0, 'partial sums over ranks differ from the serial sum at '// &
                        'some shared node (the data is adversarial): '//itoa(ndiff)//' nodes')
      end if
   end subroutine run_shared_sum

   function itoa(i) result(s)
      integer, intent(in) :: i
      character(:), allocatable :: s
      character(16) :: b
      write(b, '(i0)') i
      s = trim(b)
   end function itoa

   !> A 6x5x4 hex box partitioned by METIS (dx_partition) into np ranks; the nodal mass
   !> (one value per element node, adversarial) summed with the shared lists of rank_part.
   subroutine test_metis_box()
      integer, parameter :: NX = 6, NY = 5, NZ = 4, NE = NX*NY*NZ, NN = (NX + 1)*(NY + 1)*(NZ + 1)
      integer :: conn(8, NE), ewgt(NE), i, j, k, e, gp(1), ge(0)
      real(wp) :: val(1, 8, NE), ref(1, NN)
      integer(int64) :: st
      type(partition_t) :: part
      type(rank_part_t) :: rp
      type(model_t) :: model
      integer, allocatable :: holders(:, :)
      e = 0
      do k = 0, NZ - 1
         do j = 0, NY - 1
            do i = 0, NX - 1
               e = e + 1
               conn(:, e) = [nid(i, j, k), nid(i + 1, j, k), nid(i + 1, j + 1, k), &
                  nid(i, j + 1, k), nid(i, j, k + 1), nid(i + 1, j, k + 1), &
                  nid(i + 1, j + 1, k + 1), nid(i, j + 1, k + 1)]
            end do
         end do
      end do
      st = 777_int64
      do e = 1, NE
         do k = 1, 8
            val(1, k, e) = adversarial(st)
         end do
      end do
      ref = 0.0_wp
      do e = 1, NE
         do k = 1, 8
            ref(:, conn(k, e)) = ref(:, conn(k, e)) + val(:, k, e)
         end do
      end do
      ewgt = 1
      gp = 1
      call partition_elements(conn, NN, ewgt, gp, ge, np, part, error)
      call check_all(.not. allocated(error), 'METIS partition of the 6x5x4 box')
      if (allocated(error)) return
      ! the holders from the rank files' content: every rank's node list
      allocate(holders(0:np - 1, NN))
      holders = 0
      do i = 0, np - 1
         call rank_part(model, part, i, rp, error)
         holders(i, rp%nodes) = 1
      end do
      call run_shared_sum(NE, NN, conn, part%epart, val, ref, holders, 'METIS box')
   end subroutine test_metis_box

   !> Node number of grid point (a, b, c) of the 6x5x4 box.
   pure integer function nid(a, b, c)
      integer, intent(in) :: a, b, c
      nid = 1 + a + 7*(b + 6*c)
   end function nid
end program mpi_par_test
